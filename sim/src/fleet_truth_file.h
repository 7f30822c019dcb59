// SPDX-License-Identifier: MIT
// The fleet scenario's truth as a JSON file beside the store: every wheel's wear rate and
// reprofiling dates, every drifting sensor, each locomotive's daily distance; and read back for
// the comparison with `flange wear`'s estimate (docs/fleet.md has the fields).
#pragma once

#include <filesystem>
#include <string>

#include "fleet_day.h"
#include "fleet_plan.h"

namespace flange::sim {

void write_fleet_truth(const std::filesystem::path& path, const FleetTruth& truth,
                       const FleetRecording& recording, const std::string& generated_by);

// The fields write_fleet_truth wrote: settings, names, wheels (rates, initial wear, reprofiled
// days), day_km and drifts; wear_mm and ambient_c are left empty. Throws BadArgument naming the
// file and the field.
FleetTruth read_fleet_truth(const std::filesystem::path& path);

}  // namespace flange::sim
