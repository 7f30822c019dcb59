// SPDX-License-Identifier: MIT
#include "loco_scenario.h"

#include <cmath>

namespace flange::sim {

LocoScenario::LocoScenario(const LocoRun& run, double fs_hz, double duration_s)
    : run_(run),
      fs_hz_(fs_hz),
      duration_s_(duration_s),
      sample_count_(sample_count_for(fs_hz, duration_s)),
      lap_m_(lap_length_m(run.track)),
      wheelset_(run.wheelset),
      heating_(run.brakes) {}

double LocoScenario::lateral_force_n(double t_s) const {
  const double lap_position_m = std::fmod(run_.track.speed_mps * t_s, lap_m_);
  const double curve_n = wheelset_.supported_mass_kg() * unbalanced_acceleration_mps2(run_.track) *
                         curve_share(run_.track, lap_position_m);
  const double irregularity_n =
      wheelset_.mass_kg() * irregularity_acceleration_mps2(run_.track, lap_position_m);
  return curve_n - irregularity_n;
}

TrueState LocoScenario::next() {
  const double target_t_s = static_cast<double>(next_sample_++) / fs_hz_;
  // Equal sub-steps no longer than internal_step_s, landing exactly on the sample instant.
  const double span_s = target_t_s - t_s_;
  if (span_s > 0.0) {
    const auto steps = static_cast<std::int64_t>(std::ceil(span_s / run_.internal_step_s - 1e-9));
    const double dt_s = span_s / static_cast<double>(steps);
    const auto force = [this](double t) { return lateral_force_n(t); };
    for (std::int64_t k = 0; k < steps; ++k) {
      const double t = t_s_ + static_cast<double>(k) * dt_s;
      wheelset_.step(t, dt_s, force);
      heating_.advance(t, dt_s);
    }
    t_s_ = target_t_s;
  }
  const double worn_share = duration_s_ > 0.0 ? target_t_s / duration_s_ : 0.0;
  const double clearance_mm = run_.initial_clearance_mm + run_.wear_over_run_mm * worn_share -
                              wheelset_.displacement_m() * 1e3;
  return {target_t_s, clearance_mm, heating_.temperature_c()};
}

}  // namespace flange::sim
