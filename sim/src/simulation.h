// SPDX-License-Identifier: MIT
// Runs a scenario through the sensor twin and streams the recording out, row by row.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <limits>

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

}  // namespace flange::sim
