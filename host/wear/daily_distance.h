// SPDX-License-Identifier: MIT
// How far a locomotive runs per calendar day, from the odometer at its runs: the mean (depot days
// included), its standard error and how much the km to come scatter about it. A locomotive
// records at the start of every day it runs (the fleet scenario does, and so does a board that
// records at each start of service), so a day without a run is a day in the depot: the odometer's
// step from one run to the next is that run's day's km, and the days between ran 0 km. Over the
// history's days X_d: mu = sum X / days, sigma^2 = sum (X_d - mu)^2 / (days - 1).
//
// Days are not independent: a roster keeps a locomotive on one duty (a route, a diagram) for
// weeks and changes it at a week's start, so a run of weeks can lie above or below the mean and
// the mean of a few months, and the km of the weeks to come, scatter more than independent days
// would give. The history is cut into whole weeks counted back from its last day, and their means
// W_j (k of them) are taken as an AR(1) series: phi is the lag-1 autocorrelation of W, held to
// [0, kMaxWeekCorrelation]. The long-run variance of a day's km (the variance of a sum of n days
// over n, for n large) is
//   lambda^2 = 7 var(W) (1 + phi) / (1 - phi),
// and se mu = lambda / sqrt(days). phi is taken as estimated, without Kendall's small-sample
// correction (phi k + 1) / (k - 3): on independent days the clip at 0 keeps the upper half of the
// corrected phi's scatter and widens the dates' interval past its level (84 % at 80 % on the
// 3000 locomotives of tests/host/wear_interval_test.cpp), while the plain phi's downward bias of
// about 1 / k offsets the clip there (82 %); on weeks that are correlated it leaves phi somewhat
// low, so the interval comes near its level from below (87 % at 95 % in the same test's roster).
// Its degrees of freedom are the weeks' effective number
// k (1 - phi^2) / (1 + phi^2), less one. With fewer than kMinWeeksForCorrelation weeks the days
// are taken as independent (lambda = sigma, days - 1 degrees of freedom). The forecast's days
// and their interval are made from these (limit_forecast.h).
#pragma once

#include <vector>

#include "wheel_history.h"

namespace flange::host {

// A roster's cycle: a locomotive's duty changes at most at a week's start, so a week's mean holds
// the days' correlation within it and only the weeks' own correlation is left to estimate.
inline constexpr int kRosterWeekDays = 7;
// The weeks below which the week-to-week correlation is not estimated: a lag-1 autocorrelation of
// fewer than 8 values scatters by more than 0.35 (1 / sqrt(k)) and is biased low by over 1 / 8.
inline constexpr int kMinWeeksForCorrelation = 8;
// The most week-to-week correlation credited: (1 + phi) / (1 - phi) reaches 19, so a few weeks
// that happen to trend cannot make the interval unbounded. A negative phi is not credited: it
// would narrow the interval on what, over a few months, is mostly noise.
inline constexpr double kMaxWeekCorrelation = 0.9;

struct DailyDistance {
  double km_per_day = 0.0;        // mu; 0 when the runs span no time
  double se = 0.0;                // of mu: lambda / sqrt(days)
  double day_sd = 0.0;            // sigma: one day's km about mu
  double long_run_sd = 0.0;       // lambda: a sum of n days scatters by lambda sqrt(n)
  double week_correlation = 0.0;  // phi (0 when the days are taken as independent)
  int dof = 0;                    // of se (and lambda)
};

// `runs` in time order. Fewer than two gaps give the mean alone (se and sigma 0).
DailyDistance daily_distance(const std::vector<WearObservation>& runs);

}  // namespace flange::host
