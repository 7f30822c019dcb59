// SPDX-License-Identifier: MIT
// A bench session made here, not by the twin, for the unit tests of the free shapes' searches: the
// micrometer sweeps 1.5-10 mm in a triangle of 240 s, the blower heats towards 98 degC for 600 s
// and the sensor then cools towards 20 degC; the recorded voltage is the nominal eq. 3.14 model's.
// A test adds to that nominal voltage the gap it wants a family to find.
#pragma once

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "polynomial_sensor_model.h"
#include "recorded_part.h"
#include "recording_series.h"
#include "twin_replay.h"

namespace flange::diagnose {

class SyntheticBench {
 public:
  // `drop_one_in`: a logger that loses every that many-th row (0: none lost).
  explicit SyntheticBench(double fs_hz = 6.0, double duration_s = 1800.0, double phase_s = 0.0,
                          int drop_one_in = 0)
      : series_(make_series(fs_hz, duration_s, phase_s, drop_one_in)), replay_(series_, nominal()) {}
  SyntheticBench(const SyntheticBench&) = delete;
  SyntheticBench& operator=(const SyntheticBench&) = delete;

  RecordedPart part() const { return {series_, replay_}; }
  const RecordingSeries& series() const { return series_; }
  const TwinReplay& replay() const { return replay_; }
  std::size_t size() const { return series_.size(); }

  static sim::PolynomialSensorModel nominal() {
    return sim::PolynomialSensorModel::thesis_eq_3_14();
  }
  static double clearance_at(double t, double phase_s) {
    const double u = std::fmod(t + phase_s, 240.0) / 240.0;
    return 1.5 + 8.5 * (u < 0.5 ? 2.0 * u : 2.0 - 2.0 * u);
  }
  static double temperature_at(double t) {
    const double heat_s = 600.0;
    const double peak = 20.0 + 78.0 * (1.0 - std::exp(-heat_s / 250.0));
    return t < heat_s ? 20.0 + 78.0 * (1.0 - std::exp(-t / 250.0))
                      : 20.0 + (peak - 20.0) * std::exp(-(t - heat_s) / 400.0);
  }

 private:
  static RecordingSeries make_series(double fs_hz, double duration_s, double phase_s,
                                     int drop_one_in) {
    const sim::PolynomialSensorModel model = nominal();
    RecordingSeries s;
    for (int i = 0; i <= static_cast<int>(duration_s * fs_hz); ++i) {
      if (drop_one_in > 0 && i % drop_one_in == drop_one_in - 1) continue;
      const double t = i / fs_hz;
      s.t_s.push_back(t);
      s.clearance_mm.push_back(clearance_at(t, phase_s));
      s.temp_c.push_back(temperature_at(t));
      s.voltage_v.push_back(model.voltage_for(s.clearance_mm.back(), s.temp_c.back()).volts);
    }
    return s;
  }

  RecordingSeries series_;
  TwinReplay replay_;
};

// White noise of `sigma_v`, seeded.
inline std::vector<double> white_noise(std::size_t n, double sigma_v, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal(0.0, sigma_v);
  std::vector<double> noise(n);
  for (double& v : noise) v = normal(rng);
  return noise;
}

}  // namespace flange::diagnose
