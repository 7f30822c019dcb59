// SPDX-License-Identifier: MIT
// Piecewise-linear bases ("hats") on evenly spread knots, and how far a curve on them goes on
// beyond the calibration part's range (its reach), decided on the calibration part itself.
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <utility>
#include <vector>

#include "recorded_part.h"

namespace flange::diagnose::free_shapes {

// Knots of a curve of temperature or voltage: enough to bend twice over a heating cycle or the
// voltage range, few enough that each holds thousands of samples of a bench session.
inline constexpr int kKnots = 7;
// Knots of a picked curve of temperature refitted finer (selection/free_refit.h,
// refine_temperature_curves): about 5 degC apart over a 20-80 degC session, the kKnots among them.
// A wavy offset or gain may turn within a few degC, where kKnots name its class but leave 40-60 %
// of its gap above the noise (docs/diagnose_figures.md: on the third reality's rule-setting seeds
// 301-308, 3 more singles and 2 more pairs of two or three named first, none lost). Classes are
// still chosen on kKnots: chosen on 13, curves took other classes' shapes.
// Test: FreeRefit.APickedCurveOfTemperatureRefittedFinerExplainsAWavyGain.
inline constexpr int kFineKnots = 13;
// How far a curve of temperature goes on beyond the calibration part's range, in knot spacings
// (about 10 degC for a 20-80 degC session) before it is held.
inline constexpr double kTemperatureReach = 1.0;

// Hat k is 1 at knot k, 0 at the others; beyond the ends the end hats stay at 1 (the curve is
// held constant there). With a reach > 0 the curve goes on along its end segment for up to that
// many knot spacings beyond that end before it is held: a temperature the held-out session
// reaches a little past the calibration one's, where holding the curve flat would break a trend
// every formula continues.
struct Hats {
  std::vector<double> knots;
  double reach_below = 0.0, reach_above = 0.0;
  void reach_both(double reach) { reach_below = reach_above = reach; }
  double weight(std::size_t k, double x) const {
    const double lo = knots.front(), hi = knots.back();
    const double step = (hi - lo) / static_cast<double>(knots.size() - 1);
    if (step <= 0.0) return k == 0 ? 1.0 : 0.0;
    const double last = static_cast<double>(knots.size() - 1);
    const double u = std::clamp((x - lo) / step, -reach_below, last + reach_above);
    if (u < 0.0) return k == 0 ? 1.0 - u : k == 1 ? u : 0.0;
    if (u > last) {
      const double beyond = u - last;
      return k + 1 == knots.size() ? 1.0 + beyond : k + 2 == knots.size() ? -beyond : 0.0;
    }
    return std::max(0.0, 1.0 - std::abs(u - static_cast<double>(k)));
  }
  // The knots [first, last] whose weight at `x` may be other than +0.0: at most four around x,
  // so that a column of every row costs what its non-zero weights cost.
  std::pair<std::size_t, std::size_t> support(double x) const {
    const std::size_t count = knots.size();
    const double lo = knots.front(), hi = knots.back();
    const double step = (hi - lo) / static_cast<double>(count - 1);
    if (!(step > 0.0) || std::isnan(x)) return {0, count - 1};  // every knot, as weight() has it
    const double u = std::clamp((x - lo) / step, 0.0, static_cast<double>(count - 1));
    const auto below = static_cast<std::size_t>(u);
    return {below > 0 ? below - 1 : 0, std::min(count - 1, below + 2)};
  }
};

double knot_spacing(const Hats& hats);

// `count` knots spread evenly from lo to hi.
Hats hats_between(double lo, double hi, std::size_t count);

// `count` knots spread evenly over the range of `x`.
Hats hats_over(const std::vector<double>& x, int count);

// A family's columns on the calibration part with hats `h` in place of its own.
using ColumnsWith = std::function<Eigen::MatrixXd(const Hats& h)>;

// How far a curve goes on past each end of the calibration part's range, decided on that part
// itself: the family is fitted again with its knots over the range less `band` at each end, and
// the samples in each band are predicted with the curve going on `near` and `far` past that end
// (both in the variable's units); the end keeps `far` when that leaves less there, over at least
// kLeastSamplesToDecideReach samples, else `near`. `x` is the variable the hats are over.
void choose_reach(Hats& hats, const std::vector<double>& x, const std::vector<double>& gap_v,
                  double band, double near, double far, const ColumnsWith& columns_with);

// choose_reach for a curve of temperature: kTemperatureReach knot spacings past an end, or
// kTemperatureFarReach where the calibration part's own band at that end says so.
void choose_temperature_reach(Hats& hats, const RecordedPart& calibration,
                              const std::vector<double>& gap_v, const ColumnsWith& columns_with);

}  // namespace flange::diagnose::free_shapes
