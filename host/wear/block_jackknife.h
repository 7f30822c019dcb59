// SPDX-License-Identifier: MIT
// How far the wear line's rate can be trusted when its errors are correlated from run to run.
// A wheel's clearance carries, besides each run's own scatter, errors that move slowly: the
// season's temperature leftovers (the calibration is exact at no temperature, the ambient drifts
// over weeks), a sensor's creep, a run's reference. The least-squares standard error treats them
// as independent and is too small.
//
// Delete-a-block jackknife over time: the history is cut into B stretches of equal calendar
// length (about kBlockDays each, 3 to 8 of them), the line refitted B times with one stretch
// left out, and var r = (B - 1) / B sum_b (r_(b) - mean r_(.))^2 with B - 1 degrees of freedom.
// Errors correlated within a stretch move it together, so leaving it out shows how much the
// rate leans on them. The ratio of the jackknife's variance to the least-squares one (the
// inflation) scales the whole least-squares covariance, so the forecast's clearance now, whose
// intercept may rest on a few runs after a reprofiling, widens with the rate. One wheel's B - 1
// degrees of freedom are few: the fleet's wheels steady each other's inflation
// (moderated_spread.h) before an interval is made. On a trending history the jackknife is biased
// upward (a stretch left out at either end takes much of the odometer's leverage with it), the
// more so the fewer the stretches; it is not floored at the least-squares figure.
#pragma once

#include <functional>
#include <optional>

#include "wear_line_fit.h"

namespace flange::host {

// The stretch left out at a time: longer than the spells most slow errors come in (a spell of
// weather, a route's week), short enough to leave five or six stretches in a quarter's history
// so that each wheel's jackknife has some degrees of freedom of its own before the fleet's
// prior steadies it (moderated_spread.h). Six-week stretches (three in a quarter) overstate the
// rate's variance about threefold on errors that last days: leaving out a third of a trending
// history takes much of the odometer's leverage with it (docs/fleet.md, step 5).
inline constexpr double kBlockDays = 21.0;
// A wheel with a drift fitted out: its drift terms trade off against the rate over the whole
// time since the onset, so the stretches stay long (and its own jackknife is not moderated).
inline constexpr double kDriftBlockDays = 42.0;
inline constexpr int kMinBlocks = 3;
inline constexpr int kMaxBlocks = 8;

struct SerialSpread {
  double rate_se = 0.0;    // mm per km
  double inflation = 1.0;  // (rate_se / fit.rate_se)^2
  int dof = 0;             // Student t's: blocks - 1, or fit.dof when no jackknife could be made
  int blocks = 0;          // stretches the refits left out (0: none)
};

struct JackknifeVariance {
  double variance = 0.0;  // (B - 1) / B sum_b (t_(b) - mean t_(.))^2
  int dof = 0;            // B - 1
};

// The delete-a-block jackknife of `statistic` (of a series): the history cut into `blocks`
// stretches of equal calendar length, `statistic` taken on the series without each in turn
// (segments renumbered, shared regressors kept row by row). None when the history spans no time,
// or a stretch's leaving out leaves a series `statistic` cannot be taken on (it throws
// std::invalid_argument).
std::optional<JackknifeVariance> block_jackknife(
    const WearSeries& series, int blocks,
    const std::function<double(const WearSeries&)>& statistic);

// B for a history spanning `span_days`: round(span / block_days) within [kMinBlocks,
// kMaxBlocks].
int jackknife_blocks(double span_days, double block_days = kBlockDays);

// `fit` is fit_wear_line(series, drift_onset_day, drift_degree). A stretch whose leaving out
// leaves too few runs for the model makes the whole jackknife fall back on the least-squares
// figures (blocks 0).
SerialSpread jackknife_rate(const WearSeries& series, std::optional<double> drift_onset_day,
                            int drift_degree, const WearLineFit& fit,
                            double block_days = kBlockDays);

}  // namespace flange::host
