// SPDX-License-Identifier: MIT
#include "heating_plan.h"

#include <algorithm>
#include <cmath>

namespace flange::third_reality {
namespace {

double segment_value(const HeatingSegment& s, double from_c, double dt_s) {
  if (s.ramp_c_per_s > 0.0) {
    const double reach_s = std::abs(s.target_c - from_c) / s.ramp_c_per_s;
    if (dt_s >= reach_s) return s.target_c;
    return from_c + (s.target_c > from_c ? 1.0 : -1.0) * s.ramp_c_per_s * dt_s;
  }
  return s.target_c + (from_c - s.target_c) * std::exp(-dt_s / s.tau_s);
}

void settle(HeatingPlan& plan) {
  plan.start_c.assign(plan.segments.size(), plan.room_c);
  for (std::size_t i = 1; i < plan.segments.size(); ++i) {
    const HeatingSegment& before = plan.segments[i - 1];
    plan.start_c[i] =
        segment_value(before, plan.start_c[i - 1], plan.segments[i].start_s - before.start_s);
  }
}

// Heat towards `peak` from `on_s`, off at `off_s`: two segments.
void add_blower(HeatingPlan& plan, double on_s, double off_s, double peak, ThirdRandom& random) {
  plan.segments.push_back({on_s, peak, random.uniform(300.0, 900.0), 0.0});
  plan.segments.push_back({off_s, plan.room_c, random.uniform(500.0, 1300.0), 0.0});
}

}  // namespace

const char* heating_kind_name(HeatingKind kind) {
  switch (kind) {
    case HeatingKind::kBlowerCycle:
      return "blower_cycle";
    case HeatingKind::kOvenRamp:
      return "oven_ramp";
    case HeatingKind::kTwoBlowerCycles:
      return "two_blower_cycles";
    case HeatingKind::kHotPlateSteps:
      return "hot_plate_steps";
  }
  return "?";
}

double HeatingPlan::operator()(double t_s) const {
  if (segments.empty() || t_s < segments.front().start_s) return room_c;
  std::size_t i = segments.size() - 1;
  while (i > 0 && segments[i].start_s > t_s) --i;
  return segment_value(segments[i], start_c[i], t_s - segments[i].start_s);
}

HeatingPlan draw_heating_plan(HeatingKind kind, double duration_s, ThirdRandom& random) {
  HeatingPlan plan;
  plan.kind = kind;
  plan.room_c = random.uniform(14.0, 28.0);
  const double peak = random.uniform(65.0, 98.0);
  switch (kind) {
    case HeatingKind::kBlowerCycle:
      add_blower(plan, 0.0, duration_s * random.uniform(0.35, 0.55), peak, random);
      break;
    case HeatingKind::kOvenRamp: {
      const double rate = random.uniform(0.015, 0.06);
      const double hold_s = random.uniform(200.0, 900.0);
      plan.segments.push_back({0.0, peak, 0.0, rate});
      const double off_s = std::min((peak - plan.room_c) / rate + hold_s, 0.7 * duration_s);
      plan.segments.push_back({off_s, plan.room_c, random.uniform(600.0, 1400.0), 0.0});
      break;
    }
    case HeatingKind::kTwoBlowerCycles:
      add_blower(plan, 0.0, duration_s * random.uniform(0.15, 0.25), peak, random);
      add_blower(plan, duration_s * random.uniform(0.4, 0.5), duration_s * random.uniform(0.6, 0.7),
                 random.uniform(50.0, peak), random);
      break;
    case HeatingKind::kHotPlateSteps: {
      const int steps = 3 + random.below(3);
      for (int s = 0; s < steps; ++s) {
        const double target = plan.room_c + (peak - plan.room_c) * (s + 1) / steps;
        plan.segments.push_back(
            {duration_s * 0.75 * s / steps, target, random.uniform(150.0, 500.0), 0.0});
      }
      plan.segments.push_back({duration_s * 0.75, plan.room_c, random.uniform(500.0, 1200.0), 0.0});
      break;
    }
  }
  settle(plan);
  return plan;
}

nlohmann::json heating_plan_json(const HeatingPlan& plan) {
  nlohmann::json segments = nlohmann::json::array();
  for (const HeatingSegment& s : plan.segments) {
    segments.push_back({{"start_s", s.start_s},
                        {"target_c", s.target_c},
                        {"tau_s", s.tau_s},
                        {"ramp_c_per_s", s.ramp_c_per_s}});
  }
  return {{"kind", heating_kind_name(plan.kind)}, {"room_c", plan.room_c}, {"segments", segments}};
}

}  // namespace flange::third_reality
