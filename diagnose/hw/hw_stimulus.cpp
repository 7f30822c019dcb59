// SPDX-License-Identifier: MIT
#include "hw_stimulus.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <fstream>
#include <numbers>
#include <random>

#include "input_error.h"
#include "staged_fixed_point.h"
#include "stimulus.h"

namespace flange::diagnose {

using host::InputError;
namespace {

// Uniform in [-1, 1) from the top 53 bits of each draw (the same on every standard library).
std::vector<double> uniform(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<double> u(n);
  for (double& v : u) v = std::ldexp(static_cast<double>(rng() >> 11), -52) - 1.0;
  return u;
}

std::vector<double> read_csv(const std::string& path, std::size_t limit, int sample_width) {
  std::ifstream in(path);
  if (!in) throw InputError(fmt::format("{}: cannot open the stimulus file", path));
  const double hi = std::ldexp(1.0, sample_width - 1) - 1.0;
  std::vector<double> samples;
  std::string line;
  std::size_t number = 0;
  while (samples.size() < limit && std::getline(in, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const std::string field = line.substr(0, line.find(','));
    if (field.empty() || field[0] == '#') continue;
    double v = 0.0;
    const char* end = field.data() + field.size();
    const auto [ptr, ec] = std::from_chars(field.data(), end, v);
    if (ec != std::errc() || ptr != end || !std::isfinite(v)) {
      if (number == 1) continue;  // a header line
      throw InputError(
          fmt::format("{}:{}: column 1: '{}' is not a number (valid: a sample in "
                      "LSB, [{}, {}])",
                      path, number, field, -hi - 1, hi));
    }
    if (v < -hi - 1 || v > hi) {
      throw InputError(
          fmt::format("{}:{}: column 1: sample {} is outside [{}, {}] (LSB of the "
                      "{}-bit input)",
                      path, number, field, -hi - 1, hi, sample_width));
    }
    samples.push_back(v);
  }
  if (samples.empty()) throw InputError(fmt::format("{}: no samples in the stimulus file", path));
  return samples;
}

}  // namespace

HwStimulus make_hw_stimulus(const HwStimulusSpec& spec) {
  if (spec.samples == 0) throw InputError("--samples: must be >= 1");
  const double full = std::ldexp(1.0, spec.sample_width - 1);
  const std::size_t n = spec.samples;
  HwStimulus s;
  const std::string& kind = spec.kind;
  if (kind == "random" || kind == "fullscale") {
    const double level = kind == "random" ? 0.5 : 1.0;
    for (double u : uniform(n, spec.seed)) s.analog.push_back(level * full * u);
  } else if (kind == "sweep") {
    const double f0 = spec.fc_hz / 20;
    const double f1 = 0.49 * spec.fs_hz;
    const double duration = static_cast<double>(n) / spec.fs_hz;
    for (std::size_t i = 0; i < n; ++i) {
      const double t = static_cast<double>(i) / spec.fs_hz;
      s.analog.push_back(0.7 * full * std::sin(tb::exponential_chirp_phase(f0, f1, duration, t)));
    }
  } else if (kind == "step") {
    s.analog.assign(n, 0.5 * full);
  } else if (kind == "impulse") {
    s.analog.assign(n, 0.0);
    s.analog[0] = full - 1.0;
  } else if (kind.ends_with(".csv")) {
    s.analog = read_csv(kind, n, spec.sample_width);
  } else {
    throw InputError(fmt::format(
        "--stimulus '{}': expected random, fullscale, sweep, step, impulse or FILE.csv", kind));
  }
  for (double x : s.analog) s.words.push_back(model::round_input_sample(x, spec.sample_width));
  return s;
}

}  // namespace flange::diagnose
