// SPDX-License-Identifier: MIT
// A blind self-test's claims as selftest.json lists them, each with its confidence and whether
// it was right: what bench/confidence_reliability.sh gathers into the reliability table.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "diagnosis.h"

namespace flange::diagnose {

// [{"class", "confidence", "right"}] for each claim, `effects` in the verdict's order and
// `claimed` (the class each names) with `right` beside it.
nlohmann::json claims_json(const std::vector<EffectFinding>& effects,
                           const std::vector<std::string>& claimed, const std::vector<bool>& right);

}  // namespace flange::diagnose
