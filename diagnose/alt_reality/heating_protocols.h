// SPDX-License-Identifier: MIT
// The alternative bench's heating: three protocols that are none of the twin's blower cycle (an
// oven ramp with a plateau, two shorter blower cycles, a hot plate stepped through setpoints).
// Each is a closed-form temperature of the session clock, so any instant can be evaluated
// (a skewed channel samples between the sample times).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "alt_random.h"

namespace flange::alt_reality {

enum class HeatingKind { kOvenRamp, kTwoBlowerCycles, kHotPlateSteps };
inline constexpr int kHeatingKinds = 3;
std::string heating_kind_name(HeatingKind kind);

struct HeatingProtocol {
  HeatingKind kind = HeatingKind::kOvenRamp;
  double room_c = 20.0;          // before the session and what it cools towards
  double peak_c = 90.0;          // oven: plateau; blower: first target; plate: last setpoint
  double second_peak_c = 70.0;   // blower: the second cycle's target
  double rate_c_per_s = 0.04;    // oven: ramp rate
  double hold_s = 600.0;         // oven: plateau length; plate: time at each setpoint
  double heating_tau_s = 400.0;  // blower and plate: first-order approach to the target
  double cooling_tau_s = 900.0;  // every protocol: first-order cooling towards room_c
  int steps = 3;                 // plate: setpoints
  double duration_s = 6000.0;    // the session's length
};

// A protocol of `kind` with parameters drawn for one session of `duration_s`.
HeatingProtocol draw_heating(HeatingKind kind, double duration_s, AltRandom& random);

// The temperature around sensor and disk at session time `t_s` (room temperature before 0).
double ambient_c(const HeatingProtocol& protocol, double t_s);

nlohmann::json heating_json(const HeatingProtocol& protocol);

}  // namespace flange::alt_reality
