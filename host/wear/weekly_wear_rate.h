// SPDX-License-Identifier: MIT
// How a locomotive's wear per km moves from week to week, for the rate to come in the dates'
// interval. The forecast runs each wheel on at its history's mean rate, and the rate's interval
// holds how well the history's runs fix that mean; but a locomotive's duty (a route, a diagram:
// more curves, another load) sets how fast all its flanges wear per km, a roster keeps it on one
// duty for weeks and changes it at a week's start, and the weeks to a limit are other weeks than
// the history's: their mean rate scatters about the history's as the mean of that many weeks
// does. The km to come are handled so already (daily_distance.h); this is the same for the wear
// per km.
//
// The locomotive's wheels share its duty, so they are taken together: each wheel whose line is
// wear alone (no drift fitted out) and whose rate r is positive turns each run's clearance into
// km at its own rate, u = (y - a_seg) / r + km_0 (the km its line puts that wear at), and per run
// the median over the wheels (a day whose wheelset centring moved one wheel, or one bad wheel,
// does not move it) is the locomotive's wear in km at a rate of one. Over each whole week counted
// back from the last run (at least kMinRunsPerWeek runs), its least-squares slope on the odometer
// is the week's relative rate R_j (1: the wheels' history mean). A week's slope also carries the
// runs' own scatter, which the rate's interval holds already: its least-squares variance s_j^2
// (from the week's residuals) is taken away, var_d = var(R) - mean(s_j^2), and nothing is left
// when that is not positive (a duty that does not move the rate). As for the km per day, the
// weeks are an AR(1): phi the lag-1 autocovariance over var_d (white scatter has none), held to
// [0, kMaxWeekCorrelation], and
//   lambda_R^2 = 7 var_d (1 + phi) / (1 - phi),
// the long-run relative variance of a day's rate, with the weeks' effective number less one as
// its degrees of freedom; with fewer than kMinWeeksForCorrelation weeks there is none. The mean
// rate over the D days to come then has the relative variance lambda_R^2 / D (limit_forecast.h).
// A duty that changes the km per day as well moves both; the two are taken as independent.
#pragma once

#include <vector>

#include "daily_distance.h"
#include "wear_line_fit.h"
#include "wheel_history.h"

namespace flange::host {

// The fewest runs in a week for its slope: two give a slope with no check on a bad run, three
// let the least-squares line average one out.
inline constexpr int kMinRunsPerWeek = 3;

// One wheel of the locomotive: its runs (time order), segments and line.
struct WeeklyWearWheel {
  const std::vector<WearObservation>* runs = nullptr;
  const std::vector<int>* segment = nullptr;
  const WearLineFit* fit = nullptr;
};

struct WeeklyWearRate {
  double long_run_variance = 0.0;  // lambda_R^2, per day (relative); 0: not estimated
  double week_correlation = 0.0;   // phi
  int weeks = 0;                   // with a slope
  int dof = 0;                     // of lambda_R^2
};

WeeklyWearRate weekly_wear_rate(const std::vector<WeeklyWearWheel>& wheels);

}  // namespace flange::host
