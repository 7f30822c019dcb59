// SPDX-License-Identifier: MIT
// A recording the twin makes on a bench whose micrometer and oven follow given curves of time:
// what the diagnosis's tests feed it where the twin's own scenarios do not fit.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "recording_series.h"
#include "sensor_twin.h"

namespace flange::diagnose {

// Samples at `fs_hz` from t = 0 to `duration_s`; `clearance_mm(t)` and `temp_c(t)` are the
// reference clearance and the oven's temperature. The recorded temperature is the twin's reading.
template <class Clearance, class Temperature>
RecordingSeries record_twin(const sim::TwinConfig& config, std::uint64_t seed, double fs_hz,
                            double duration_s, Clearance clearance_mm, Temperature temp_c) {
  sim::SensorTwin twin(config, seed);
  RecordingSeries series;
  const auto n = static_cast<int>(duration_s * fs_hz);
  for (int i = 0; i <= n; ++i) {
    const double t = i / fs_hz;
    const double d = clearance_mm(t);
    const sim::Reading r = twin.step({t, d, temp_c(t)});
    series.t_s.push_back(t);
    series.clearance_mm.push_back(d);
    series.temp_c.push_back(r.temp_c);
    series.voltage_v.push_back(r.voltage_v);
  }
  return series;
}

// The micrometer over 1.5-10 mm in 0.5 mm steps, up and down: 20 s at each position, 4 s moves.
inline double staircase_mm(double t) {
  constexpr double kMove = 4.0, kDwell = 20.0;
  std::vector<double> seq;
  for (int k = 0; k < 18; ++k) seq.push_back(1.5 + 0.5 * k);
  for (int k = 16; k > 0; --k) seq.push_back(1.5 + 0.5 * k);
  const double step = kMove + kDwell;
  const double u = std::fmod(t, step * static_cast<double>(seq.size()));
  const auto k = static_cast<std::size_t>(u / step);
  const double r = u - static_cast<double>(k) * step;
  const double a = seq[k], b = seq[(k + 1) % seq.size()];
  return r < kDwell ? a : a + (b - a) * (r - kDwell) / kMove;
}

}  // namespace flange::diagnose
