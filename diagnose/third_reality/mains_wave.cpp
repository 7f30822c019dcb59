// SPDX-License-Identifier: MIT
#include "mains_wave.h"

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "band_motion.h"

namespace flange::third_reality {

double MainsWave::operator()(double absolute_s) const {
  double cycles = (nominal_hz + offset_hz) * absolute_s;
  for (std::size_t j = 0; j < swing_hz.size(); ++j) {
    // The integral of swing sin(2 pi t / P + q) over t, in cycles.
    cycles -= swing_hz[j] * swing_period_s[j] / (2.0 * std::numbers::pi) *
              std::cos(2.0 * std::numbers::pi * absolute_s / swing_period_s[j] + swing_phase[j]);
  }
  const double phase = 2.0 * std::numbers::pi * (cycles - std::floor(cycles));
  double sum = std::sin(phase);
  for (std::size_t h = 0; h < harmonic.size(); ++h) {
    sum += harmonic[h] * std::sin(static_cast<double>(h + 2) * phase + harmonic_phase[h]);
  }
  return sum;
}

double usable_mains_hz(double fs_hz, ThirdRandom& random) {
  std::vector<double> usable;
  for (double f : {50.0, 60.0}) {
    if (shows_as_a_line(f, fs_hz, 0.3)) usable.push_back(f);
  }
  if (usable.empty()) return 0.0;
  return usable[static_cast<std::size_t>(random.below(static_cast<int>(usable.size())))];
}

MainsWave draw_mains_wave(double nominal_hz, ThirdRandom& random) {
  MainsWave wave;
  wave.nominal_hz = nominal_hz;
  wave.offset_hz = random.uniform(-0.05, 0.05);
  for (std::size_t j = 0; j < wave.swing_hz.size(); ++j) {
    wave.swing_hz[j] = random.log_uniform(0.002, 0.04);
    wave.swing_period_s[j] = random.log_uniform(60.0, 1800.0);
    wave.swing_phase[j] = random.uniform(0.0, 2.0 * std::numbers::pi);
  }
  for (std::size_t h = 0; h < wave.harmonic.size(); ++h) {
    wave.harmonic[h] = random.chance(0.5) ? random.uniform(0.05, 0.6) : 0.0;
    wave.harmonic_phase[h] = random.uniform(0.0, 2.0 * std::numbers::pi);
  }
  return wave;
}

void put_mains_wave(const MainsWave& wave, Params& params) {
  params["nominal_hz"] = wave.nominal_hz;
  params["offset_hz"] = wave.offset_hz;
  for (std::size_t j = 0; j < wave.swing_hz.size(); ++j) {
    const std::string key = "swing" + std::to_string(j);
    params[key + "_hz"] = wave.swing_hz[j];
    params[key + "_period_s"] = wave.swing_period_s[j];
    params[key + "_phase"] = wave.swing_phase[j];
  }
  for (std::size_t h = 0; h < wave.harmonic.size(); ++h) {
    const std::string key = "harmonic" + std::to_string(h + 2);
    params[key] = wave.harmonic[h];
    params[key + "_phase"] = wave.harmonic_phase[h];
  }
}

MainsWave get_mains_wave(const Params& params) {
  MainsWave wave;
  wave.nominal_hz = params.at("nominal_hz");
  wave.offset_hz = params.at("offset_hz");
  for (std::size_t j = 0; j < wave.swing_hz.size(); ++j) {
    const std::string key = "swing" + std::to_string(j);
    wave.swing_hz[j] = params.at(key + "_hz");
    wave.swing_period_s[j] = params.at(key + "_period_s");
    wave.swing_phase[j] = params.at(key + "_phase");
  }
  for (std::size_t h = 0; h < wave.harmonic.size(); ++h) {
    const std::string key = "harmonic" + std::to_string(h + 2);
    wave.harmonic[h] = params.at(key);
    wave.harmonic_phase[h] = params.at(key + "_phase");
  }
  return wave;
}

}  // namespace flange::third_reality
