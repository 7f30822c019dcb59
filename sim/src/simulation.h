// SPDX-License-Identifier: MIT
// Runs a scenario through the sensor twin and streams the recording out, row by row; or every
// wheel of a locomotive, each through its own twin into its own recording.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <limits>
#include <vector>

#include "locomotive.h"
#include "scenario.h"
#include "sensor_twin.h"

namespace flange::sim {

struct SimulationSummary {
  std::int64_t samples = 0;
  RailClipCounts clips;
  double min_clearance_mm = std::numeric_limits<double>::infinity();
  double max_clearance_mm = -std::numeric_limits<double>::infinity();
  double min_temp_c = std::numeric_limits<double>::infinity();  // as the thermocouple read it
  double max_temp_c = -std::numeric_limits<double>::infinity();
};

// Writes the header and every sample of `scenario` through `twin` to `csv`.
SimulationSummary run_simulation(Scenario& scenario, SensorTwin& twin, std::ostream& csv);

// Writes every wheel of `locomotive` through twins[c] to *csvs[c] (one twin and one stream per
// wheel, in channel order); one summary per wheel.
std::vector<SimulationSummary> run_locomotive_simulation(Locomotive& locomotive,
                                                         std::vector<SensorTwin>& twins,
                                                         const std::vector<std::ostream*>& csvs);

}  // namespace flange::sim
