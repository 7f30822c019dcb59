// SPDX-License-Identifier: MIT
// The third bench's heating, of the kinds both other benches use: one blower cycle (heat
// towards a target, off, cool back), an oven ramp to a plateau, two blower cycles, and a hot plate
// stepped through rising setpoints. Each is a list of segments (a first-order approach to a
// target, or a straight ramp to it), evaluable at any instant.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "third_random.h"

namespace flange::third_reality {

enum class HeatingKind { kBlowerCycle, kOvenRamp, kTwoBlowerCycles, kHotPlateSteps };
inline constexpr int kHeatingKinds = 4;
const char* heating_kind_name(HeatingKind kind);

struct HeatingSegment {
  double start_s = 0.0;
  double target_c = 20.0;
  double tau_s = 600.0;       // a first-order approach to the target (when ramp_c_per_s == 0)
  double ramp_c_per_s = 0.0;  // > 0: a straight ramp to the target, then held
};

struct HeatingPlan {
  HeatingKind kind = HeatingKind::kBlowerCycle;
  double room_c = 20.0;
  std::vector<HeatingSegment> segments;  // by start time, the first at 0
  std::vector<double> start_c;           // the temperature at each segment's start
  double operator()(double t_s) const;   // room temperature before 0
};

HeatingPlan draw_heating_plan(HeatingKind kind, double duration_s, ThirdRandom& random);

nlohmann::json heating_plan_json(const HeatingPlan& plan);

}  // namespace flange::third_reality
