// SPDX-License-Identifier: MIT
#include "wheelset_lateral.h"

#include <cmath>
#include <numbers>

namespace flange::sim {

double lead_damping_ns_per_m(const WheelsetLateralParameters& p) {
  return 2.0 * p.lead_damping_ratio * std::sqrt(p.wheelset_mass_kg * p.lead_stiffness_n_per_m);
}

double lateral_natural_frequency_hz(const WheelsetLateralParameters& p) {
  return std::sqrt(p.leads * p.lead_stiffness_n_per_m / p.wheelset_mass_kg) /
         (2.0 * std::numbers::pi);
}

WheelsetLateral::WheelsetLateral(const WheelsetLateralParameters& p)
    : mass_kg_(p.wheelset_mass_kg),
      stiffness_n_per_m_(p.leads * p.lead_stiffness_n_per_m),
      damping_ns_per_m_(p.leads * lead_damping_ns_per_m(p)),
      gap_m_(p.bump_stop_gap_m),
      stop_stiffness_n_per_m_(p.bump_stop_stiffness_n_per_m),
      supported_mass_kg_(p.supported_mass_kg) {}

double WheelsetLateral::acceleration(double x, double v, double force_n) const {
  double stop_n = 0.0;  // the bump stop engages only beyond the allowed play
  if (x > gap_m_) stop_n = stop_stiffness_n_per_m_ * (x - gap_m_);
  if (x < -gap_m_) stop_n = stop_stiffness_n_per_m_ * (x + gap_m_);
  return (force_n - damping_ns_per_m_ * v - stiffness_n_per_m_ * x - stop_n) / mass_kg_;
}

}  // namespace flange::sim
