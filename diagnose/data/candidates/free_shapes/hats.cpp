// SPDX-License-Identifier: MIT
#include "hats.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "ridge_solve.h"

namespace flange::diagnose::free_shapes {
namespace {

// The fewest calibration samples in an end's band that decide its reach: a sum of squares over
// 100 samples of noise varies by about 14 % (sqrt(2 / 100)) by chance; over fewer, the noise
// would choose the reach.
constexpr std::size_t kLeastSamplesToDecideReach = 100;
// A curve of temperature goes on kTemperatureReach knot spacings past an end, or this many where
// the calibration part says so: a quadratic offset or gain goes on bending over a held-out
// session that heats 15-20 degC further than the calibration one. Judged on a band of
// kTemperatureBand knot spacings at each end.
constexpr double kTemperatureFarReach = 3.0;
constexpr double kTemperatureBand = 1.5;

}  // namespace

double knot_spacing(const Hats& hats) {
  return (hats.knots.back() - hats.knots.front()) / static_cast<double>(hats.knots.size() - 1);
}

Hats hats_between(double lo, double hi, std::size_t count) {
  Hats hats;
  for (std::size_t k = 0; k < count; ++k) {
    hats.knots.push_back(lo + (hi - lo) * static_cast<double>(k) / static_cast<double>(count - 1));
  }
  return hats;
}

Hats hats_over(const std::vector<double>& x, int count) {
  const auto [lo, hi] = std::minmax_element(x.begin(), x.end());
  return hats_between(*lo, *hi, static_cast<std::size_t>(count));
}

void choose_reach(Hats& hats, const std::vector<double>& x, const std::vector<double>& gap_v,
                  double band, double near, double far, const ColumnsWith& columns_with) {
  const auto in_knots = [](const Hats& h, double distance) {
    const double spacing = knot_spacing(h);
    return spacing > 0.0 ? distance / spacing : 0.0;
  };
  hats.reach_both(in_knots(hats, near));
  const double lo = hats.knots.front(), hi = hats.knots.back();
  const double inner_lo = lo + band, inner_hi = hi - band;
  if (inner_hi - inner_lo < band) return;
  const Hats inner = hats_between(inner_lo, inner_hi, hats.knots.size());
  // The inner fit's columns are let go before the ends' are made: at 100 Hz each is tens of MB,
  // and two curve families search at once.
  const Eigen::VectorXd beta = [&] {
    const Eigen::MatrixXd all = columns_with(inner);
    std::vector<Eigen::Index> rows;
    for (std::size_t i = 0; i < x.size(); ++i) {
      if (x[i] >= inner_lo && x[i] <= inner_hi) rows.push_back(static_cast<Eigen::Index>(i));
    }
    Eigen::MatrixXd a(static_cast<Eigen::Index>(rows.size()), all.cols());
    Eigen::VectorXd y(static_cast<Eigen::Index>(rows.size()));
    for (std::size_t r = 0; r < rows.size(); ++r) {
      a.row(static_cast<Eigen::Index>(r)) = all.row(rows[r]);
      y(static_cast<Eigen::Index>(r)) = gap_v[static_cast<std::size_t>(rows[r])];
    }
    return Eigen::VectorXd(ridge_solve(a, y));
  }();
  // What the inner fit, going on `reach` past one end, leaves on the samples in that end's band.
  const auto left_in_band = [&](bool below, double reach) {
    Hats way = inner;
    way.reach_both(in_knots(inner, near));
    (below ? way.reach_below : way.reach_above) = in_knots(inner, reach);
    const Eigen::VectorXd fitted = columns_with(way) * beta;
    double sum = 0.0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < x.size(); ++i) {
      if (below ? x[i] >= inner_lo : x[i] <= inner_hi) continue;
      sum += std::pow(gap_v[i] - fitted(static_cast<Eigen::Index>(i)), 2);
      ++n;
    }
    return std::pair{sum, n};
  };
  for (const bool below : {true, false}) {
    const auto [at_near, n] = left_in_band(below, near);
    if (n < kLeastSamplesToDecideReach || left_in_band(below, far).first >= at_near) continue;
    (below ? hats.reach_below : hats.reach_above) = in_knots(hats, far);
  }
}

void choose_temperature_reach(Hats& hats, const RecordedPart& calibration,
                              const std::vector<double>& gap_v, const ColumnsWith& columns_with) {
  // In the spacing of kKnots, whatever the curve's own: the reach is a distance in degC.
  const double spacing = knot_spacing(hats) * static_cast<double>(hats.knots.size() - 1) /
                         static_cast<double>(kKnots - 1);
  choose_reach(hats, calibration.series.temp_c, gap_v, kTemperatureBand * spacing,
               kTemperatureReach * spacing, kTemperatureFarReach * spacing, columns_with);
}

}  // namespace flange::diagnose::free_shapes
