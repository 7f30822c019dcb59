// SPDX-License-Identifier: MIT
#include "heating_protocols.h"

#include <algorithm>
#include <cmath>

namespace flange::alt_reality {
namespace {

// First order from `from_c` towards `target_c`, `dt_s` after the start.
double approach(double from_c, double target_c, double tau_s, double dt_s) {
  return target_c + (from_c - target_c) * std::exp(-dt_s / tau_s);
}

double oven_ramp(const HeatingProtocol& p, double t_s) {
  const double ramp_end_s = (p.peak_c - p.room_c) / p.rate_c_per_s;
  if (t_s < ramp_end_s) return p.room_c + p.rate_c_per_s * t_s;
  const double hold_end_s = ramp_end_s + p.hold_s;
  if (t_s < hold_end_s) return p.peak_c;
  return approach(p.peak_c, p.room_c, p.cooling_tau_s, t_s - hold_end_s);
}

// Two cycles, each heating for 45 % of its half of the session, then cooling.
double two_blower_cycles(const HeatingProtocol& p, double t_s) {
  const double cycle_s = p.duration_s / 2.0;
  const double on_s = 0.45 * cycle_s;
  double start_c = p.room_c;
  for (int cycle = 0; cycle < 2; ++cycle) {
    const double target_c = cycle == 0 ? p.peak_c : p.second_peak_c;
    const double t = t_s - cycle * cycle_s;
    const double off_c = approach(start_c, target_c, p.heating_tau_s, on_s);
    if (t < on_s) return approach(start_c, target_c, p.heating_tau_s, t);
    if (cycle == 1 || t < cycle_s) return approach(off_c, p.room_c, p.cooling_tau_s, t - on_s);
    start_c = approach(off_c, p.room_c, p.cooling_tau_s, cycle_s - on_s);
  }
  return p.room_c;
}

// Setpoints room + (peak - room) j / steps, each held for hold_s, then the plate is off.
double hot_plate_steps(const HeatingProtocol& p, double t_s) {
  double from_c = p.room_c;
  for (int j = 1; j <= p.steps; ++j) {
    const double setpoint_c = p.room_c + (p.peak_c - p.room_c) * j / p.steps;
    const double t = t_s - (j - 1) * p.hold_s;
    if (t < p.hold_s) return approach(from_c, setpoint_c, p.heating_tau_s, t);
    from_c = approach(from_c, setpoint_c, p.heating_tau_s, p.hold_s);
  }
  return approach(from_c, p.room_c, p.cooling_tau_s, t_s - p.steps * p.hold_s);
}

}  // namespace

std::string heating_kind_name(HeatingKind kind) {
  switch (kind) {
    case HeatingKind::kOvenRamp:
      return "oven_ramp";
    case HeatingKind::kTwoBlowerCycles:
      return "two_blower_cycles";
    case HeatingKind::kHotPlateSteps:
      return "hot_plate_steps";
  }
  return "?";
}

HeatingProtocol draw_heating(HeatingKind kind, double duration_s, AltRandom& random) {
  HeatingProtocol p;
  p.kind = kind;
  p.duration_s = duration_s;
  p.room_c = random.uniform(12.0, 26.0);
  p.peak_c = random.uniform(65.0, 95.0);
  p.second_peak_c = random.uniform(45.0, 80.0);
  p.rate_c_per_s = random.uniform(0.02, 0.06);
  p.heating_tau_s = random.uniform(250.0, 700.0);
  p.cooling_tau_s = random.uniform(500.0, 1500.0);
  p.steps = 3 + random.index(2);
  // Oven: the plateau takes what the ramp leaves of the first 55 %; plate: 70 % is heated.
  const double ramp_s = (p.peak_c - p.room_c) / p.rate_c_per_s;
  p.hold_s = kind == HeatingKind::kOvenRamp ? std::max(120.0, 0.55 * duration_s - ramp_s)
                                            : 0.7 * duration_s / p.steps;
  return p;
}

double ambient_c(const HeatingProtocol& protocol, double t_s) {
  if (t_s <= 0.0) return protocol.room_c;
  switch (protocol.kind) {
    case HeatingKind::kOvenRamp:
      return oven_ramp(protocol, t_s);
    case HeatingKind::kTwoBlowerCycles:
      return two_blower_cycles(protocol, t_s);
    case HeatingKind::kHotPlateSteps:
      return hot_plate_steps(protocol, t_s);
  }
  return protocol.room_c;
}

nlohmann::json heating_json(const HeatingProtocol& p) {
  return {{"kind", heating_kind_name(p.kind)},
          {"room_c", p.room_c},
          {"peak_c", p.peak_c},
          {"second_peak_c", p.second_peak_c},
          {"rate_c_per_s", p.rate_c_per_s},
          {"hold_s", p.hold_s},
          {"heating_tau_s", p.heating_tau_s},
          {"cooling_tau_s", p.cooling_tau_s},
          {"steps", p.steps},
          {"duration_s", p.duration_s}};
}

}  // namespace flange::alt_reality
