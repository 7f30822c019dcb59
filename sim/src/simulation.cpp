// SPDX-License-Identifier: MIT
#include "simulation.h"

#include <algorithm>
#include <stdexcept>

#include "recording_writer.h"

namespace flange::sim {
namespace {

// One recording being made: the truth through a twin into a writer, and its summary so far.
class ChannelRecorder {
 public:
  ChannelRecorder(SensorTwin& twin, std::ostream& csv) : twin_(twin), writer_(csv) {}

  void record(const TrueState& truth) {
    const Reading reading = twin_.step(truth);
    writer_.write(truth, reading);
    ++summary_.samples;
    summary_.min_clearance_mm = std::min(summary_.min_clearance_mm, truth.clearance_mm);
    summary_.max_clearance_mm = std::max(summary_.max_clearance_mm, truth.clearance_mm);
    summary_.min_temp_c = std::min(summary_.min_temp_c, reading.temp_c);
    summary_.max_temp_c = std::max(summary_.max_temp_c, reading.temp_c);
  }

  SimulationSummary finish() {
    summary_.clips = twin_.clip_counts();
    return summary_;
  }

 private:
  SensorTwin& twin_;
  RecordingWriter writer_;
  SimulationSummary summary_;
};

}  // namespace

SimulationSummary run_simulation(Scenario& scenario, SensorTwin& twin, std::ostream& csv) {
  ChannelRecorder recorder(twin, csv);
  for (std::int64_t n = 0; n < scenario.sample_count(); ++n) recorder.record(scenario.next());
  return recorder.finish();
}

std::vector<SimulationSummary> run_locomotive_simulation(Locomotive& locomotive,
                                                         std::vector<SensorTwin>& twins,
                                                         const std::vector<std::ostream*>& csvs) {
  const auto wheels = static_cast<std::size_t>(locomotive.wheels());
  if (twins.size() != wheels || csvs.size() != wheels) {
    throw std::invalid_argument("run_locomotive_simulation: one twin and one stream per wheel");
  }
  std::vector<ChannelRecorder> recorders;
  recorders.reserve(wheels);
  for (std::size_t c = 0; c < wheels; ++c) recorders.emplace_back(twins[c], *csvs[c]);
  for (std::int64_t n = 0; n < locomotive.sample_count(); ++n) {
    const std::vector<TrueState>& truth = locomotive.next();
    for (std::size_t c = 0; c < wheels; ++c) recorders[c].record(truth[c]);
  }
  std::vector<SimulationSummary> summaries;
  summaries.reserve(wheels);
  for (ChannelRecorder& recorder : recorders) summaries.push_back(recorder.finish());
  return summaries;
}

}  // namespace flange::sim
