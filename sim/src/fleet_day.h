// SPDX-License-Identifier: MIT
// One locomotive's day in the fleet scenario: the recording its twelve sensors make at the start
// of the day's service. The loco scenario's locomotive on the depot's route (the thesis's curve
// and irregularity with a long tangent after them), that day's ambient under the brake heating,
// every wheel's flange as worn as the fleet's truth says, every sensor through its own twin
// (a drifting one with its ageing drift as old as that day).
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "fleet_plan.h"
#include "locomotive.h"
#include "sensor_twin.h"
#include "simulation.h"

namespace flange::sim {

struct FleetRecording {
  double fs_hz = 6.0;         // > 0: the thesis's DAQ rate, what the measurement filter expects
  double duration_s = 240.0;  // > 0: 4 minutes of service, 2.4 laps of the route
  // The depot's route: the thesis's lap with 1590 m of tangent after the curve (a 2 km lap,
  // 80 % tangent), so that the wheelset runs centred on most of a recording.
  double route_tangent_out_m = 1590.0;
  // Clearance over a new flange: the thesis's sensor setting (ThresholdConfig::sensor_gap_mm).
  double new_flange_clearance_mm = 2.0;
};

// The locomotive's run on `day`: the route, that day's ambient.
LocoRun fleet_day_run(const FleetTruth& truth, int day, const FleetRecording& recording);

// Every wheel's flange over the recording: its clearance at the start of the day's service and
// the little wear the recording's own distance adds.
std::vector<FlangeWear> fleet_day_flanges(const FleetTruth& truth, int locomotive, int day,
                                          const FleetRecording& recording);

// `base` with the sensor's ageing drift switched on when (locomotive, channel) drifts by `day`.
TwinConfig fleet_day_twin(const TwinConfig& base, const FleetTruth& truth, int locomotive,
                          int channel, int day);

// The seed of the twin of (locomotive, channel) on `day`: independent streams of the fleet's seed.
std::uint64_t fleet_twin_seed(std::uint64_t seed, int locomotive, int day, int channel);

// Writes the day's recording of every wheel to dir/channel_XX.csv (12 files, channel order);
// one summary per wheel. Throws std::runtime_error when a file cannot be written.
std::vector<SimulationSummary> simulate_fleet_day(const FleetTruth& truth, int locomotive, int day,
                                                  const FleetRecording& recording,
                                                  const TwinConfig& base,
                                                  const std::filesystem::path& dir);

}  // namespace flange::sim
