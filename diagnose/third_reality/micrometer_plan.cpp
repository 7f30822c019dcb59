// SPDX-License-Identifier: MIT
#include "micrometer_plan.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace flange::third_reality {
namespace {

// One pass of the kind's positions between low and high.
std::vector<double> positions_of(MicrometerKind kind, double low, double high, double step,
                                 ThirdRandom& random) {
  std::vector<double> up;
  for (double d = low; d <= high + 1e-9; d += step) up.push_back(d);
  if (kind == MicrometerKind::kUpDownStaircase) {
    std::vector<double> pass = up;
    for (auto it = up.rbegin() + 1; it != up.rend(); ++it) pass.push_back(*it);
    return pass;
  }
  if (kind == MicrometerKind::kRandomPositions) {
    for (std::size_t i = up.size(); i > 1; --i) {
      std::swap(up[i - 1], up[static_cast<std::size_t>(random.below(static_cast<int>(i)))]);
    }
  }
  return up;  // the snap-back staircase climbs, and the next pass starts at the bottom
}

}  // namespace

const char* micrometer_kind_name(MicrometerKind kind) {
  switch (kind) {
    case MicrometerKind::kUpDownStaircase:
      return "up_down_staircase";
    case MicrometerKind::kRandomPositions:
      return "random_positions";
    case MicrometerKind::kSineSweep:
      return "sine_sweep";
    case MicrometerKind::kSnapBackStaircase:
      return "snap_back_staircase";
  }
  return "?";
}

double MicrometerPlan::operator()(double t_s) const {
  if (kind == MicrometerKind::kSineSweep) {
    const double mid = 0.5 * (low_mm + high_mm), half = 0.5 * (high_mm - low_mm);
    return mid + half * std::sin(2.0 * std::numbers::pi * t_s / period_s + phase);
  }
  const auto next = std::upper_bound(arrive_s.begin(), arrive_s.end(), t_s);
  if (next == arrive_s.begin()) return position_mm.front();
  const auto i = static_cast<std::size_t>(next - arrive_s.begin()) - 1;
  if (i + 1 >= arrive_s.size()) return position_mm[i];
  const double leave_s = arrive_s[i + 1] - move_s;
  if (t_s <= leave_s) return position_mm[i];
  const double s = (t_s - leave_s) / move_s;
  return position_mm[i] +
         (position_mm[i + 1] - position_mm[i]) * 0.5 * (1.0 - std::cos(std::numbers::pi * s));
}

MicrometerPlan draw_micrometer_plan(MicrometerKind kind, double duration_s, ThirdRandom& random) {
  MicrometerPlan plan;
  plan.kind = kind;
  plan.low_mm = random.uniform(1.5, 3.0);
  plan.high_mm = random.uniform(7.0, 10.0);
  plan.move_s = random.uniform(2.0, 8.0);
  if (kind == MicrometerKind::kSineSweep) {
    plan.period_s = random.uniform(120.0, 900.0);
    plan.phase = random.uniform(0.0, 2.0 * std::numbers::pi);
    return plan;
  }
  const double step = random.uniform(0.4, 1.5);
  const double dwell_s = random.uniform(12.0, 60.0);
  double t = 0.0;
  while (t <= duration_s) {
    for (double d : positions_of(kind, plan.low_mm, plan.high_mm, step, random)) {
      plan.arrive_s.push_back(t);
      plan.position_mm.push_back(d);
      t += dwell_s + plan.move_s;
    }
  }
  return plan;
}

nlohmann::json micrometer_plan_json(const MicrometerPlan& plan) {
  nlohmann::json j = {{"kind", micrometer_kind_name(plan.kind)},
                      {"low_mm", plan.low_mm},
                      {"high_mm", plan.high_mm}};
  if (plan.kind == MicrometerKind::kSineSweep) {
    j["period_s"] = plan.period_s;
    j["phase"] = plan.phase;
  } else {
    j["move_s"] = plan.move_s;
    j["arrive_s"] = plan.arrive_s;
    j["position_mm"] = plan.position_mm;
  }
  return j;
}

}  // namespace flange::third_reality
