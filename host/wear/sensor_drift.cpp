// SPDX-License-Identifier: MIT
#include "sensor_drift.h"

#include <cmath>
#include <stdexcept>

namespace flange::host {
namespace {

struct Candidate {
  bool left = true;
  double onset_day = 0.0;
  WearLineFit fit;
};

// The side and onset whose drift fits the difference best (smallest residual). The drift of
// either sensor enters the difference through that sensor's own slope.
std::optional<Candidate> best_candidate(const WearSeries& difference, const WearSeries& left,
                                        const WearSeries& right) {
  std::optional<Candidate> best;
  const std::size_t n = difference.day.size();
  for (const bool is_left : {true, false}) {
    WearSeries series = difference;
    series.drift_scale = (is_left ? left : right).drift_scale;
    for (std::size_t k = 0; k + kMinRunsAfterOnset < n; ++k) {
      try {
        WearLineFit fit = fit_wear_line(series, difference.day[k], kDriftDegree);
        if (!best || fit.rss < best->fit.rss) best = Candidate{is_left, difference.day[k], fit};
      } catch (const std::invalid_argument&) {
        break;  // too few points for the drift model
      }
    }
  }
  return best;
}

double last_scale(const WearSeries& series) {
  return series.drift_scale.empty() ? 1.0 : series.drift_scale.back();
}

// The drift by the last run over its standard error, in a wheel's own series.
double own_drift_t(const WearSeries& series, double onset_day) {
  const DriftValue drift = drift_at(fit_wear_line(series, onset_day, kDriftDegree),
                                    series.day.back(), last_scale(series));
  return drift.se > 0.0 ? drift.mm / drift.se : 0.0;
}

// The flagged drift in one combination of the two wheels (their difference or their sum).
std::optional<DriftFinding> drift_in(const WearSeries& difference, const WearSeries& left_series,
                                     const WearSeries& right_series) {
  const std::optional<Candidate> best = best_candidate(difference, left_series, right_series);
  if (!best) return std::nullopt;
  const WearSeries& fitted_side = best->left ? left_series : right_series;
  const DriftValue drift = drift_at(best->fit, difference.day.back(), last_scale(fitted_side));
  const double t = drift.se > 0.0 ? drift.mm / drift.se : 0.0;
  if (std::abs(t) < kDriftTStatistic || std::abs(drift.mm) < kMinDriftMm) return std::nullopt;
  DriftFinding finding;
  // The faulty sensor: the one whose own series carries the drift more strongly (the other's
  // own series has only what the two share).
  finding.left = std::abs(own_drift_t(left_series, best->onset_day)) >
                 std::abs(own_drift_t(right_series, best->onset_day));
  const WearSeries& own = finding.left ? left_series : right_series;
  finding.onset_day = best->onset_day;
  finding.difference_t = t;
  finding.size_mm = std::abs(drift.mm);
  const DriftValue own_drift =
      drift_at(fit_wear_line(own, best->onset_day, kDriftDegree), own.day.back(), last_scale(own));
  finding.rate_mm_per_day = own_drift.mm / (own.day.back() - best->onset_day);
  return finding;
}

// One sensor's drift moves the sum and the difference by as much; what both wheels share (a
// step of both flanges the data did not show as a reprofiling, the season) moves only the sum.
// A drift found in the sum is a sensor's only when the difference, fitted with the same onset
// and slope, has moved by at least half as much.
bool shows_in_difference(const DriftFinding& in_sum, const WearSeries& difference,
                         const WearSeries& left_series, const WearSeries& right_series) {
  const WearSeries& side = in_sum.left ? left_series : right_series;
  WearSeries series = difference;
  series.drift_scale = side.drift_scale;
  const DriftValue moved = drift_at(fit_wear_line(series, in_sum.onset_day, kDriftDegree),
                                    difference.day.back(), last_scale(side));
  return std::abs(moved.mm) >= 0.5 * in_sum.size_mm;
}

}  // namespace

std::optional<DriftFinding> find_sensor_drift(const WearSeries& difference,
                                              const WearSeries& left_series,
                                              const WearSeries& right_series) {
  WearSeries sum = difference;
  for (std::size_t k = 0; k < sum.y.size(); ++k) sum.y[k] = left_series.y[k] + right_series.y[k];
  std::optional<DriftFinding> found = drift_in(difference, left_series, right_series);
  std::optional<DriftFinding> in_sum = drift_in(sum, left_series, right_series);
  if (in_sum && !shows_in_difference(*in_sum, difference, left_series, right_series)) {
    in_sum.reset();
  }
  if (in_sum) in_sum->in_sum = true;
  if (!found || (in_sum && std::abs(in_sum->difference_t) > std::abs(found->difference_t))) {
    return in_sum;
  }
  return found;
}

}  // namespace flange::host
