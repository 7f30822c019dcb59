// SPDX-License-Identifier: MIT
// The improved twin in diagnosis.json and in the HTML report: how the twin written beside them
// (twin.json) holds each finding, and what it cannot hold.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "improved_twin.h"

namespace flange::diagnose {

// The file name the twin is written under, beside diagnosis.json.
inline constexpr const char* kImprovedTwinFile = "twin.json";

nlohmann::ordered_json improved_twin_json(const ImprovedTwin& twin);
// An HTML section (heading, sentence and table).
std::string improved_twin_html(const ImprovedTwin& twin);

}  // namespace flange::diagnose
