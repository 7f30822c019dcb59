// SPDX-License-Identifier: MIT
// `flange wear`'s tables: wear.json (every wheel: each run's estimate, the reprofilings, the
// rate with its interval, the sensor fault, the forecasts) and wear.csv (one row per wheel, the
// fleet table's columns).
#pragma once

#include <filesystem>
#include <string>

#include "fleet_wear.h"

namespace flange::host {

void write_wear_json(const std::filesystem::path& path, const FleetWear& fleet,
                     const std::string& generated_by);

void write_wear_csv(const std::filesystem::path& path, const FleetWear& fleet);

// The fleet table as printed on stdout.
std::string fleet_wear_text(const FleetWear& fleet);

// "12 km" style figures with their interval, "-" when unknown.
std::string interval_text(const std::optional<double>& value, const std::optional<double>& low,
                          const std::optional<double>& high, int decimals);

}  // namespace flange::host
