// SPDX-License-Identifier: MIT
// `flange wear`'s HTML page: the fleet table sorted by days to the warning clearance, and per
// locomotive small multiples of wear against odometer (one panel per wheel, axles down, left and
// right across: each run's estimate, the fitted line of each flange, the warning and critical
// wear), drawn by gnuplot into SVG.
#pragma once

#include <filesystem>
#include <string>

#include "fleet_wear.h"

namespace flange::host {

// Writes DIR/index.html and DIR/wear_<locomotive>.svg (DIR exists). `sections_html`, when
// given, goes after the fleet table (the reprofiling plan: reprofiling_plan.h).
void write_wear_report(const std::filesystem::path& dir, const FleetWear& fleet,
                       const std::string& generated_by, const std::string& sections_html = "");

}  // namespace flange::host
