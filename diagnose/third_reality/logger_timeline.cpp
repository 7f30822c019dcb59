// SPDX-License-Identifier: MIT
#include "logger_timeline.h"

#include <algorithm>
#include <cmath>

namespace flange::third_reality {

LoggerPlan draw_logger_plan(double fs_hz, ThirdRandom& random) {
  LoggerPlan plan;
  plan.jitter_s = random.uniform(0.0, std::min(0.004, 0.1 / fs_hz));
  plan.drop_fraction = random.log_uniform(0.001, 0.02);
  plan.longest_burst = 1 + random.below(20);
  plan.seed = random.child_seed();
  return plan;
}

LoggerTimeline logger_timeline(const LoggerPlan& plan, double fs_hz, double duration_s,
                               bool with_logger) {
  LoggerTimeline timeline;
  ThirdRandom random(static_cast<std::uint64_t>(plan.seed));
  const auto rows = static_cast<std::size_t>(std::floor(duration_s * fs_hz)) + 1;
  // A burst starts with the probability that makes the drop fraction on average.
  const double mean_burst = 0.5 * (1.0 + plan.longest_burst);
  const double burst_start = plan.drop_fraction / mean_burst;
  const double clip_s = 1.0 / (3.0 * fs_hz);
  int losing = 0;
  for (std::size_t k = 0; k < rows; ++k) {
    const double instant = static_cast<double>(k) / fs_hz;
    const double jitter = std::clamp(plan.jitter_s * random.normal(), -clip_s, clip_s);
    const bool starts = random.chance(burst_start);
    const int length = 1 + random.below(plan.longest_burst);
    if (!with_logger) {
      timeline.instant_s.push_back(instant);
      timeline.stamp_s.push_back(instant);
      continue;
    }
    if (losing == 0 && starts && k > 0) losing = length;
    if (losing > 0) {
      --losing;
      ++timeline.dropped;
      continue;
    }
    timeline.instant_s.push_back(instant);
    timeline.stamp_s.push_back(k == 0 ? 0.0 : instant + jitter);  // the clock starts at row 1
  }
  return timeline;
}

nlohmann::json logger_plan_json(const LoggerPlan& plan) {
  return {{"jitter_s", plan.jitter_s},
          {"drop_fraction", plan.drop_fraction},
          {"longest_burst", plan.longest_burst},
          {"seed", plan.seed}};
}

}  // namespace flange::third_reality
