// SPDX-License-Identifier: MIT
#include "sensor_drift.h"

#include "wear_change_in_km.h"

#include <algorithm>
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
    for (std::size_t k = kMinRunsBeforeOnset; k + kMinRunsAfterOnset < n; ++k) {
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

// How much wider the drift's standard error is than the run-to-run scatter says, when the
// residuals are correlated from run to run (a seasonal leftover, a spell of faster wear): with
// lag-1 autocorrelation rho of an AR(1) error, a trend's variance grows by (1 + rho) / (1 - rho).
double correlation_widening(const std::vector<double>& residuals) {
  double lagged = 0.0, squares = 0.0;
  for (std::size_t k = 0; k < residuals.size(); ++k) {
    squares += residuals[k] * residuals[k];
    if (k > 0) lagged += residuals[k] * residuals[k - 1];
  }
  const double rho = squares > 0.0 ? std::clamp(lagged / squares, 0.0, 0.99) : 0.0;
  return std::sqrt((1.0 + rho) / (1.0 - rho));
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

// The best drift-like fit in one combination of the two wheels (their difference or their
// sum), whatever its size.
std::optional<DriftFinding> best_drift_in(const WearSeries& difference,
                                          const WearSeries& left_series,
                                          const WearSeries& right_series,
                                          const std::set<std::size_t>& flange_starts) {
  const std::optional<Candidate> best = best_candidate(difference, left_series, right_series);
  if (!best) return std::nullopt;
  const WearSeries& fitted_side = best->left ? left_series : right_series;
  const DriftValue drift = drift_at(best->fit, difference.day.back(), last_scale(fitted_side));
  const double se = drift.se * correlation_widening(best->fit.residuals);
  DriftFinding finding;
  // The faulty sensor: the one whose own series carries the drift more strongly (the other's
  // own series has only what the two share).
  finding.left = std::abs(own_drift_t(left_series, best->onset_day)) >
                 std::abs(own_drift_t(right_series, best->onset_day));
  const WearSeries& own = finding.left ? left_series : right_series;
  finding.onset_day = best->onset_day;
  finding.difference_t = se > 0.0 ? drift.mm / se : 0.0;
  finding.size_mm = std::abs(drift.mm);
  // A change in days, not the wear's in km (wear_change_in_km.h)? Two more onset searches, so
  // asked only of a drift that passes the thresholds no locomotive's bar lowers: on most axles
  // the search's best fit is far below them and the answer could change nothing.
  if (finding.size_mm >= kMinDriftMm && std::abs(finding.difference_t) >= kDriftTStatistic) {
    WearSeries fitted = difference;
    fitted.drift_scale = fitted_side.drift_scale;
    const auto change_rss = [&](ChangeIn in) {
      return best_change_rss(fitted, flange_starts, in, kDriftDegree, kMinRunsBeforeOnset,
                             kMinRunsAfterOnset);
    };
    finding.grows_with_days = change_rss(ChangeIn::days) < change_rss(ChangeIn::km);
  }
  const DriftValue own_drift = drift_at(fit_wear_line(own, best->onset_day, kDriftDegree),
                                        own.day.back(), last_scale(own));
  finding.rate_mm_per_day = own_drift.mm / (own.day.back() - best->onset_day);
  return finding;
}

bool flagged(const std::optional<DriftFinding>& finding, const LocomotiveBar& bar) {
  if (!finding || !finding->moved_other || !finding->grows_with_days ||
      finding->size_mm < kMinDriftMm) {
    return false;
  }
  const double t = std::abs(finding->difference_t);
  return t >= kDriftTStatistic && (t >= bar.t || finding->size_mm >= bar.size_mm);
}

// The value half of `values` reach (the upper median of an even count).
double upper_median(std::vector<double> values) {
  const auto half = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), half, values.end());
  return *half;
}

// Whether `other` (the axle's other combination), fitted with the found onset and slope, has
// moved by at least half the found drift: one sensor's drift moves the sum and the difference
// by as much (see the header).
bool moves_other(const DriftFinding& found, const WearSeries& other,
                 const WearSeries& left_series, const WearSeries& right_series) {
  const WearSeries& side = found.left ? left_series : right_series;
  WearSeries series = other;
  series.drift_scale = side.drift_scale;
  const DriftValue moved = drift_at(fit_wear_line(series, found.onset_day, kDriftDegree),
                                    other.day.back(), last_scale(side));
  return std::abs(moved.mm) >= 0.5 * found.size_mm;
}

}  // namespace

DriftCandidates drift_candidates(const WearSeries& difference, const WearSeries& left_series,
                                 const WearSeries& right_series,
                                 const std::set<std::size_t>& flange_starts) {
  WearSeries sum = difference;
  for (std::size_t k = 0; k < sum.y.size(); ++k) sum.y[k] = left_series.y[k] + right_series.y[k];
  DriftCandidates candidates;
  candidates.in_difference = best_drift_in(difference, left_series, right_series, flange_starts);
  candidates.in_sum = best_drift_in(sum, left_series, right_series, flange_starts);
  if (candidates.in_difference) {
    candidates.in_difference->moved_other =
        moves_other(*candidates.in_difference, sum, left_series, right_series);
  }
  if (candidates.in_sum) {
    candidates.in_sum->in_sum = true;
    candidates.in_sum->moved_other =
        moves_other(*candidates.in_sum, difference, left_series, right_series);
  }
  return candidates;
}

LocomotiveBar locomotive_bar(const std::vector<DriftCandidates>& axles) {
  LocomotiveBar bar;
  if (axles.size() < kMinAxlesForTypical) return bar;
  std::vector<double> ts, sizes;
  for (const DriftCandidates& axle : axles) {
    double t = 0.0, size = 0.0;
    for (const auto& finding : {axle.in_difference, axle.in_sum}) {
      if (!finding) continue;
      size = std::max(size, finding->size_mm);
      if (finding->size_mm >= kMinDriftMm) t = std::max(t, std::abs(finding->difference_t));
    }
    ts.push_back(t);
    sizes.push_back(size);
  }
  bar.t = std::max(kDriftTStatistic, kDriftTOverTypical * upper_median(ts));
  bar.size_mm = std::max(kMinDriftMm, kDriftSizeOverTypical * upper_median(sizes));
  return bar;
}

std::optional<DriftFinding> flagged_drift(const DriftCandidates& candidates,
                                          const LocomotiveBar& bar) {
  const bool in_difference = flagged(candidates.in_difference, bar);
  const bool in_sum = flagged(candidates.in_sum, bar);
  if (in_sum && (!in_difference || std::abs(candidates.in_sum->difference_t) >
                                       std::abs(candidates.in_difference->difference_t))) {
    return candidates.in_sum;
  }
  if (in_difference) return candidates.in_difference;
  return std::nullopt;
}

}  // namespace flange::host
