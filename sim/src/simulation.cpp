// SPDX-License-Identifier: MIT
#include "simulation.h"

#include <algorithm>

#include "recording_writer.h"

namespace flange::sim {

SimulationSummary run_simulation(Scenario& scenario, SensorTwin& twin, std::ostream& csv) {
  RecordingWriter writer(csv);
  SimulationSummary summary;
  for (std::int64_t n = 0; n < scenario.sample_count(); ++n) {
    const TrueState truth = scenario.next();
    const Reading reading = twin.step(truth);
    writer.write(truth, reading);
    summary.min_clearance_mm = std::min(summary.min_clearance_mm, truth.clearance_mm);
    summary.max_clearance_mm = std::max(summary.max_clearance_mm, truth.clearance_mm);
    summary.min_temp_c = std::min(summary.min_temp_c, reading.temp_c);
    summary.max_temp_c = std::max(summary.max_temp_c, reading.temp_c);
  }
  summary.samples = scenario.sample_count();
  summary.clips = twin.clip_counts();
  return summary;
}

}  // namespace flange::sim
