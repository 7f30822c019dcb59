// SPDX-License-Identifier: MIT
#include "fixed_knees.h"

#include <fmt/format.h>

#include <algorithm>
#include <vector>

#include "criteria.h"

namespace flange::diagnose {
namespace {

struct TemperatureSpan {
  double lowest_c = 0.0;
  double highest_c = 0.0;
};

// The temperatures both parts recorded.
TemperatureSpan recorded_span(const Parts& parts) {
  TemperatureSpan span{parts.calibration.temp_c.front(), parts.calibration.temp_c.front()};
  for (const RecordingSeries* s : {&parts.calibration, &parts.heldout}) {
    for (const double t : s->temp_c) {
      span.lowest_c = std::min(span.lowest_c, t);
      span.highest_c = std::max(span.highest_c, t);
    }
  }
  return span;
}

}  // namespace

void judge_fixed_knees(Selection& selection) {
  for (Pick& pick : selection.picks) {
    if (pick.step.candidates.empty() || !pick.chosen().free_shape) continue;
    const std::string& other = pick.chosen().free_shape->also_of_class;
    std::vector<std::string>& alike = pick.finding.indistinguishable_from;
    if (other.empty() || other == pick.finding.name ||
        std::find(alike.begin(), alike.end(), other) != alike.end()) {
      continue;
    }
    alike.push_back(other);
  }
}

std::string tell_fixed_knee_from_compression(const Parts& parts, const EffectFinding& pick,
                                             const std::string& other) {
  const TemperatureSpan span = recorded_span(parts);
  const std::string what = fmt::format(
      "to tell {} from {}: the curve lies over the top of the voltage range and does not move "
      "with temperature over the recorded {:.3g} to {:.3g} degC, as a static nonlinearity of the "
      "voltage and a compression with a fixed knee alike do",
      pick.name, other, span.lowest_c, span.highest_c);
  if (span.lowest_c <= criteria::kOperatingRangeLowestC &&
      span.highest_c >= criteria::kOperatingRangeHighestC) {
    return what +
           "; the recordings span the bench's operating range, so no session on it tells "
           "them apart";
  }
  return fmt::format(
      "{}; a session that holds the clearance where the voltage lies over the top of the range "
      "while the temperature sweeps {:g} to {:g} degC would: a compression's knee that moves "
      "there is {}, a curve that stays put is either",
      what, criteria::kOperatingRangeLowestC, criteria::kOperatingRangeHighestC, other);
}

}  // namespace flange::diagnose
