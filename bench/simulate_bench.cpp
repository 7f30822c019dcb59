// SPDX-License-Identifier: MIT
// Samples per second of the sensor twin: nominal model and noise only (the baseline, same run),
// then with every effect switched on at its defaults, then the whole `flange simulate` loco path
// (scenario dynamics at 1 kHz, twin, CSV formatting) into a discarding stream.
#include <benchmark/benchmark.h>

#include <cmath>
#include <ostream>
#include <streambuf>

#include "effect_catalogue.h"
#include "loco_scenario.h"
#include "recording_writer.h"
#include "sensor_twin.h"

namespace {

using flange::sim::TrueState;

// A truth that sweeps the whole sensor range and the thesis's temperatures, at 100 Hz.
TrueState sweeping_truth(std::int64_t n) {
  const double t = static_cast<double>(n) * 0.01;
  return {t, 5.75 + 4.25 * std::sin(0.1 * t), 59.0 + 39.0 * std::sin(0.013 * t)};
}

void run_twin(benchmark::State& state, const flange::sim::TwinConfig& config) {
  flange::sim::SensorTwin twin(config, 1);
  std::int64_t n = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(twin.step(sweeping_truth(n++)));
  }
  state.SetItemsProcessed(state.iterations());
}

void TwinNominalAndNoise(benchmark::State& state) { run_twin(state, flange::sim::TwinConfig{}); }

void TwinAllEffects(benchmark::State& state) {
  flange::sim::TwinConfig config;
  for (const flange::sim::EffectSpec& spec : flange::sim::effect_catalogue()) {
    // The tabulated effect takes its table from a twin file only.
    if (spec.name == flange::sim::tabulated_effect_name()) continue;
    config.effects.push_back(flange::sim::make_effect_settings(spec.name, {}, "bench"));
  }
  run_twin(state, config);
}

class DiscardingBuffer : public std::streambuf {
 protected:
  int_type overflow(int_type c) override { return c; }
  std::streamsize xsputn(const char*, std::streamsize count) override { return count; }
};

void SimulateLocoToCsv(benchmark::State& state) {
  DiscardingBuffer buffer;
  std::ostream sink(&buffer);
  flange::sim::RecordingWriter writer(sink);
  flange::sim::SensorTwin twin(flange::sim::TwinConfig{}, 1);
  // One long run, consumed a sample per iteration (1e7 samples = 27.8 h at 100 Hz).
  flange::sim::LocoScenario scenario(flange::sim::LocoRun{}, 100.0, 1e5);
  for (auto _ : state) {
    const TrueState truth = scenario.next();
    writer.write(truth, twin.step(truth));
  }
  state.SetItemsProcessed(state.iterations());
}

}  // namespace

BENCHMARK(TwinNominalAndNoise);
BENCHMARK(TwinAllEffects);
BENCHMARK(SimulateLocoToCsv)->Iterations(2000000);
BENCHMARK_MAIN();
