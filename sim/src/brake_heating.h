// SPDX-License-Identifier: MIT
// Brake heating at the sensor: while the locomotive brakes, wheel and flange heat up and warm
// the sensor beside them (thesis 2.1: flange and tread contact temperatures jump under braking
// and traction); between applications it cools back to ambient. First order both ways, with a
// schedule of brake applications.
#pragma once

namespace flange::sim {

struct BrakeHeating {
  double ambient_c = 30.0;      // a warm day on the Ethio-Djibouti line
  double first_brake_s = 20.0;  // start of the first application
  double interval_s = 120.0;    // one application every interval_s
  double brake_duration_s = 30.0;
  double rise_c = 72.0;         // the sensor heads for ambient + rise_c while braking
  double heating_tau_s = 15.0;  // ... 30 s of braking: 92-95 degC, in the thesis's 79-98 degC
  double cooling_tau_s = 90.0;
};

// True while a brake application is on at time t.
bool braking_at(const BrakeHeating& brakes, double t_s);

class SensorHeating {
 public:
  explicit SensorHeating(const BrakeHeating& brakes)
      : brakes_(brakes), temperature_c_(brakes.ambient_c) {}

  // Advances by dt_s with the brake state at t_s + dt_s / 2 held over the step (exact for a
  // piecewise-constant brake state that switches on step boundaries).
  void advance(double t_s, double dt_s);

  double temperature_c() const { return temperature_c_; }

 private:
  BrakeHeating brakes_;
  double temperature_c_;
};

}  // namespace flange::sim
