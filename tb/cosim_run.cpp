// SPDX-License-Identifier: MIT
#include "cosim_run.h"

#include <fmt/format.h>

#include <charconv>
#include <fstream>
#include <ostream>
#include <stdexcept>

#include "cosim_harness.h"
#include "iir_core.h"

namespace flange::tb {
namespace {

std::vector<std::int32_t> read_csv(const std::filesystem::path& path, std::size_t limit,
                                   int sample_width) {
  std::ifstream in(path);
  if (!in)
    throw std::invalid_argument(fmt::format("{}: cannot open the stimulus file", path.string()));
  std::vector<std::int32_t> samples;
  std::string line;
  std::size_t number = 0;
  const std::int64_t hi = (std::int64_t{1} << (sample_width - 1)) - 1;
  while (samples.size() < limit && std::getline(in, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const std::string field = line.substr(0, line.find(','));
    if (field.empty() || field[0] == '#') continue;
    std::int64_t v = 0;
    const char* end = field.data() + field.size();
    const auto [ptr, ec] = std::from_chars(field.data(), end, v);
    if (ec != std::errc() || ptr != end) {
      if (number == 1) continue;  // a header line
      throw std::invalid_argument(
          fmt::format("{}:{}: '{}' is not an integer sample", path.string(), number, field));
    }
    if (v < -hi - 1 || v > hi) {
      throw std::invalid_argument(fmt::format("{}:{}: sample {} is outside [{}, {}]", path.string(),
                                              number, v, -hi - 1, hi));
    }
    samples.push_back(static_cast<std::int32_t>(v));
  }
  if (samples.empty()) {
    throw std::invalid_argument(fmt::format("{}: no samples in the stimulus file", path.string()));
  }
  return samples;
}

}  // namespace

std::vector<std::int32_t> cosim_samples(const CosimOptions& options,
                                        const model::CoreConfig& config,
                                        const model::FloatDesign& design) {
  if (options.samples == 0) throw std::invalid_argument("--samples must be >= 1");
  SignalSpec spec;
  spec.sample_width = config.sample_width;
  spec.fs_hz = design.fs_hz;
  spec.fc_hz = design.fc_hz.value_or(design.fs_hz / 10);
  const std::size_t n = options.samples;
  const std::string& kind = options.stimulus;
  if (kind == "random") return uniform_random(spec, n, 0.5, options.seed);
  if (kind == "fullscale") return uniform_random(spec, n, 1.0, options.seed);
  if (kind == "sweep") return sine_sweep(spec, n, spec.fc_hz / 20, 0.49 * spec.fs_hz, 0.7);
  if (kind == "step") return step(spec, n, 0.5);
  if (kind == "impulse") return impulse(spec, n);
  if (kind.ends_with(".csv")) return read_csv(kind, n, config.sample_width);
  throw std::invalid_argument(fmt::format(
      "--stimulus '{}': expected random, fullscale, sweep, step, impulse or FILE.csv", kind));
}

int run_cosim(const CosimOptions& options, const DutFactory& make, std::ostream& out,
              std::ostream& err) {
  const model::CoreConfig config = model::load_core_config(options.coeffs);
  const model::FloatDesign design = model::load_float_design(options.coeffs);
  const std::vector<std::int32_t> samples = cosim_samples(options, config, design);

  CosimHarness harness(config, make(options.trace.value_or(std::filesystem::path{})));
  const int latency = harness.model().latency_cycles();
  const int cycles_per_sample = harness.model().cycles_per_sample();
  Stimulus stimulus = every(samples, static_cast<std::uint64_t>(cycles_per_sample));
  // A multichannel core gets the samples dealt to its channels in turn (round robin).
  for (std::size_t i = 0; i < stimulus.actions.size(); ++i) {
    stimulus.actions[i].channel = static_cast<int>(i % static_cast<std::size_t>(config.num_channels));
  }
  const CosimReport report = harness.run(stimulus);

  int status = 0;
  if (report.mismatches > 0) {
    err << "cosim: first mismatch: " << report.first_mismatch << "\n";
    status = 1;
  }
  if (report.rtl_assertion) {
    err << "cosim: an RTL assertion fired (its message is above)\n";
    status = 1;
  }
  if (report.outputs.size() != samples.size()) {
    err << fmt::format("cosim: {} samples in, {} outputs\n", samples.size(), report.outputs.size());
    status = 1;
  }
  if (options.trace) err << "cosim: waveform in " << options.trace->string() << "\n";
  out << fmt::format("cosim: {} samples, {} mismatches, {} cycles/sample, {} cycles latency{}\n",
                     report.accepted, report.mismatches, cycles_per_sample, latency,
                     config.num_channels > 1
                         ? fmt::format(", {} channels in turn", config.num_channels)
                         : std::string());
  return status;
}

}  // namespace flange::tb
