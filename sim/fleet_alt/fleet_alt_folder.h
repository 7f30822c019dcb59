// SPDX-License-Identifier: MIT
// `flange simulate --scenario fleet-alt --out DIR`: the second fleet reality written as a depot
// would hand it to the service path (README.md):
//   DIR/bench/bench_N.csv          the depot's bench sessions (for flange calibrate --store)
//   DIR/days/DATE/LOCO/            each recorded locomotive-day: locomotive.json, channel_XX.csv
//   DIR/runs.csv                   started_at,locomotive,manifest,distance_km,odometer_km: one
//                                  line per recorded locomotive-day, in time order, the odometer
//                                  as read on the locomotive at the recording's end
//   DIR/maintenance.csv            at,locomotive,axle,side,kind,odometer_km,from_axle,sensor: the
//                                  depot's records (axle empty: the whole locomotive; side empty:
//                                  both wheels of the axle)
//   DIR/fleet_truth.json           the truth, in the fleet scenario's format (docs/fleet.md), for
//                                  flange wear --truth
#pragma once

#include <filesystem>
#include <string>

#include "fleet_alt_plan.h"

namespace flange::fleet_alt {

inline constexpr int kBenchSessions = 3;

struct FleetAltWritten {
  int runs = 0;          // recorded locomotive-days
  int missing_days = 0;  // ran, but no recording
  int depot_days = 0;
  int reprofilings = 0;  // axles turned
};

// Throws std::runtime_error naming a file that cannot be written.
FleetAltWritten write_fleet_alt_folder(const FleetAltTruth& truth, const std::filesystem::path& dir,
                                       const std::string& generated_by);

}  // namespace flange::fleet_alt
