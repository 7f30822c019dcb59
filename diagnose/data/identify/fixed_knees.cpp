// SPDX-License-Identifier: MIT
#include "fixed_knees.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "criteria.h"
#include "curve_alike.h"
#include "effect_classes.h"
#include "series_arithmetic.h"
#include "series_statistics.h"

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

bool is_a_curve_over_the_top(const std::vector<double>& cal_v, const std::vector<double>& cal_curve,
                             const std::vector<double>& ho_v, const std::vector<double>& ho_curve,
                             const std::vector<double>& ho_left, double noise_v, int knots) {
  const std::optional<std::vector<double>> of_v =
      curve_of_one_variable_alike(cal_v, cal_curve, ho_v, ho_curve, ho_left, noise_v, knots);
  if (!of_v) return false;  // not a curve of the voltage alone
  const std::vector<double>& on_cal = *of_v;
  const double middle = median_of(cal_v);
  double lower_ss = 0.0, upper_ss = 0.0;
  std::size_t lower_n = 0, upper_n = 0;
  for (std::size_t i = 0; i < cal_v.size(); ++i) {
    if (cal_v[i] < middle) {
      lower_ss += on_cal[i] * on_cal[i];
      ++lower_n;
    } else {
      upper_ss += on_cal[i] * on_cal[i];
      ++upper_n;
    }
  }
  if (lower_n == 0 || upper_n == 0 || !lowers_the_upper_half(cal_v, on_cal)) return false;
  const double lower_rms = std::sqrt(lower_ss / static_cast<double>(lower_n));
  const double upper_rms = std::sqrt(upper_ss / static_cast<double>(upper_n));
  return lower_rms <= criteria::kMostLowerHalfShareOfACompression * upper_rms;
}

void judge_curves_over_the_top(const Parts& parts, Selection& selection) {
  const std::vector<std::size_t> named = name_classes_alike(
      parts, selection, &FreeShapeFamily::over_the_top_also_of, parts.ho_replay.nominal_voltage(),
      [&](const FreeShapeFit& shape, const HeldoutCurve& heldout) {
        return is_a_curve_over_the_top(parts.cal_replay.nominal_voltage(), shape.cal_voltage_v,
                                       heldout.x, heldout.curve, heldout.left, selection.noise_v,
                                       std::max(shape.free_values, 2));
      });
  for (const std::size_t k : named) name_the_compression_first(selection.picks[k]);
}

void name_the_compression_first(Pick& pick) {
  std::swap(pick.finding.name, pick.finding.indistinguishable_from.back());
}

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

void judge_fixed_knees(const Parts& parts, Selection& selection) {
  judge_fixed_knees(selection);
  judge_curves_over_the_top(parts, selection);
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
  const std::string& compression =
      effect_class(pick.name).function_of_clearance_alone ? other : pick.name;
  return fmt::format(
      "{}; a session that holds the clearance where the voltage lies over the top of the range "
      "while the temperature sweeps {:g} to {:g} degC would: a compression's knee that moves "
      "there is {}, a curve that stays put is either",
      what, criteria::kOperatingRangeLowestC, criteria::kOperatingRangeHighestC, compression);
}

}  // namespace flange::diagnose
