// SPDX-License-Identifier: MIT
// A finding's parameters as the report and diagnosis.json give them: a value where the data
// determine it, "undetermined" (null in JSON) where they do not, a bound ("<= -39.5") where its
// value lies at the edge of the search; and the verdict's names, each with the classes the data
// cannot tell from it.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "diagnosis.h"

namespace flange::diagnose {

// "key=value,key=undetermined,key<=bound", keys in order, and a law of the temperature's level
// inside the recording where the finding has one: ", at 22.0 degC gain_change=0.0175".
std::string params_text(const EffectFinding& finding);

// {"key": value or null (undetermined) or "<= bound"}.
nlohmann::ordered_json params_json(const EffectFinding& finding);

// A law of the temperature's level inside the recording: {"temp_c": 22.0, "gain_change": 0.0175,
// "resolution": 0.0003 or null}, or null for a finding without one.
nlohmann::ordered_json level_json(const EffectFinding& finding);

// Each parameter's resolution ({"key": value, or null where nothing in the data moves with it}).
nlohmann::ordered_json resolution_json(const EffectFinding& finding);

// "temp_gain_drift, adc_quantization", or with classes the data cannot tell apart:
// "range_compression, temp_offset_drift or ageing_drift (these data cannot tell them apart)".
std::string verdict_names(const std::vector<EffectFinding>& findings);

}  // namespace flange::diagnose
