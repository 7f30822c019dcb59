// SPDX-License-Identifier: MIT
// The second fleet reality's recordings, in the formats the service path reads: one recording
// CSV per wheel (t_s,clearance_mm,temp_c,voltage_v with the clearance empty: in service nothing
// measures it) and a locomotive.json naming each channel's wheel (docs/locomotive.md), and the
// depot's bench sessions (a micrometer stepped over the clearance at five climate-chamber
// temperatures, the reference in clearance_mm) for `flange calibrate`.
#pragma once

#include <filesystem>
#include <string>

#include "fleet_alt_plan.h"

namespace flange::fleet_alt {

// The morning's recording of locomotive `l` on `day` (which must be a recorded day) into
// `dir` (created): channel_00.csv .. channel_11.csv and locomotive.json. Throws
// std::runtime_error naming a file that cannot be written.
void write_locomotive_day(const FleetAltTruth& truth, int l, int day,
                          const std::filesystem::path& dir, const std::string& generated_by);

// Bench session `n` (1, 2, ...): a sample unit of the sensor type on the depot's bench, into
// `path`. Throws std::runtime_error when it cannot be written.
void write_bench_session(const FleetAltSettings& settings, int n,
                         const std::filesystem::path& path);

// The distance (km) of a recording on `route`.
double recording_km(const FleetAltTruth& truth, int route);

}  // namespace flange::fleet_alt
