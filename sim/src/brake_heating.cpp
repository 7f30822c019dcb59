// SPDX-License-Identifier: MIT
#include "brake_heating.h"

#include <cmath>

namespace flange::sim {

bool braking_at(const BrakeHeating& brakes, double t_s) {
  if (t_s < brakes.first_brake_s) return false;
  return std::fmod(t_s - brakes.first_brake_s, brakes.interval_s) < brakes.brake_duration_s;
}

void SensorHeating::advance(double t_s, double dt_s) {
  const bool on = braking_at(brakes_, t_s + 0.5 * dt_s);
  const double target_c = on ? brakes_.ambient_c + brakes_.rise_c : brakes_.ambient_c;
  const double tau_s = on ? brakes_.heating_tau_s : brakes_.cooling_tau_s;
  temperature_c_ = target_c + (temperature_c_ - target_c) * std::exp(-dt_s / tau_s);
}

}  // namespace flange::sim
