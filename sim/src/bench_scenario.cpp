// SPDX-License-Identifier: MIT
#include "bench_scenario.h"

#include <algorithm>
#include <cmath>

namespace flange::sim {

double bench_clearance_mm(const BenchProtocol& protocol, double t_s) {
  const auto positions =
      static_cast<std::int64_t>(std::llround(
          (protocol.last_position_mm - protocol.first_position_mm) / protocol.step_mm)) +
      1;
  // Index of the k-th position in the zigzag 0, 1, ..., n-1, n-2, ..., 1, 0, 1, ...
  const std::int64_t period = 2 * (positions - 1);
  const auto zigzag = [&](std::int64_t k) {
    const std::int64_t m = k % period;
    return m < positions ? m : period - m;
  };
  const double step_s = protocol.move_s + protocol.dwell_s;
  const auto k = static_cast<std::int64_t>(std::floor(t_s / step_s));
  const double target_mm =
      protocol.first_position_mm + protocol.step_mm * static_cast<double>(zigzag(k));
  if (k == 0) return target_mm;
  const double from_mm =
      protocol.first_position_mm + protocol.step_mm * static_cast<double>(zigzag(k - 1));
  const double progress = std::min(1.0, (t_s - static_cast<double>(k) * step_s) / protocol.move_s);
  return from_mm + (target_mm - from_mm) * progress;
}

double bench_temperature_c(const BenchProtocol& protocol, double t_s) {
  const auto heated = [&](double t) {
    return protocol.blower_target_c +
           (protocol.room_c - protocol.blower_target_c) * std::exp(-t / protocol.heating_tau_s);
  };
  if (t_s <= protocol.blower_off_s) return heated(t_s);
  const double at_off_c = heated(protocol.blower_off_s);
  return protocol.room_c + (at_off_c - protocol.room_c) *
                               std::exp(-(t_s - protocol.blower_off_s) / protocol.cooling_tau_s);
}

BenchScenario::BenchScenario(const BenchProtocol& protocol, double fs_hz, double duration_s)
    : protocol_(protocol), fs_hz_(fs_hz), sample_count_(sample_count_for(fs_hz, duration_s)) {}

TrueState BenchScenario::next() {
  // Time from the sample index, never accumulated, so long runs do not drift.
  const double t_s = static_cast<double>(next_sample_++) / fs_hz_;
  return {t_s, bench_clearance_mm(protocol_, t_s), bench_temperature_c(protocol_, t_s)};
}

}  // namespace flange::sim
