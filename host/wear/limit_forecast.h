// SPDX-License-Identifier: MIT
// When a wheel reaches a clearance limit: the fitted line of its current flange (the segment
// since the last reprofiling) extended from its last run at the fitted rate; days from distance
// at the locomotive's mean km per calendar day over its history (depot days included). With the
// fleet's acceleration b (wear_acceleration.h: dw/dkm = r exp(b (w - w_now))) the km to a gap G
// are K = (1 - exp(-b G)) / (b r), G / r as b -> 0, from the clearance and rate at the last run
// corrected for b and the history's calendar trend (c - b g_c - gamma h_c, r - b g_r - gamma h_r).
// The days K / mu are the history's mean season's; the season to come then moves them, and their
// bounds, as the cycle's sinusoid through the fleet's trend does (season_to_come.h), the km with
// them (mu times the days).
//
// The interval holds three uncertainties, combined to first order (delta method) as a relative
// standard deviation of the distance K = (limit - c) / r and of the days T = K / mu:
//   (sd K / K)^2 = (var c + (G/r)^2 var r + 2 (G/r) cov(c, r)) / G^2,  G = limit - c
//   (sd T / T)^2 = (sd K / K)^2 + (se mu / mu)^2 + lambda^2 / (mu K)
// (sd K / K)^2 also holds the rate to come's relative variance: the season the history has not
// seen (season_to_come.h) and the duties of the days to come, lambda_R^2 / T (weekly_wear_rate.h)
// (with b: the partial derivatives of K in c and r, and the variance of the fleet's b and
// gamma through K's total derivatives in them, their dof in Welch-Satterthwaite's)
// the fitted clearance now and the rate (their covariance from the wear line, which allows
// errors correlated from run to run, so it holds the reference of a flange reprofiled a few runs
// ago), the mean km per day estimated from the history (se mu) and the km the locomotive has
// yet to run, a sum of days whose long-run standard deviation is lambda (the first-passage time
// of a walk with drift mu, whose variance is K lambda^2 / mu^3; lambda and se mu allow for days
// correlated over weeks, daily_distance.h). The bounds are K / (1 +- q sd K / K) and the
// same for T: as for a rate interval, the slow end is unbounded when the ratio reaches 1 (the
// rate's interval reaches 0). q is Student t's: for K at the wear line's degrees of freedom,
// for T at the Welch-Satterthwaite degrees of freedom of its three parts (the line's, those of
// se mu, and none lost for the days to come, which are a sum of many).
#pragma once

#include <optional>
#include <string>

namespace flange::host {

struct LimitForecast {
  double limit_clearance_mm = 0.0;
  bool reached = false;           // the fitted clearance is at or past the limit already
  std::optional<double> km;       // distance left; nothing when the rate is not positive
  std::optional<double> km_low;   // at the upper rate
  std::optional<double> km_high;  // at the lower rate; nothing when it is not positive
  std::optional<double> days, days_low, days_high;
  std::string date, date_low, date_high;  // YYYY-MM-DD (date_of_day); "" when unknown
};

struct ForecastInput {
  double clearance_now_mm = 0.0;  // the fitted line at the last run
  double rate_mm_per_km = 0.0;
  double rate_low_mm_per_km = 0.0;  // 95 % interval: used alone when dof is 0
  double rate_high_mm_per_km = 0.0;
  double km_per_day = 0.0;  // > 0 for days and dates
  double last_day = 0.0;    // days since 1970-01-01 of the last run
  // The uncertainties (see above); dof 0: the interval is the rate's alone, without days'.
  double clearance_now_se_mm = 0.0;
  double rate_se_mm_per_km = 0.0;
  double clearance_rate_covariance = 0.0;  // mm^2 / km
  int dof = 0;                             // Student t's for the line's part
  double km_per_day_se = 0.0;              // of the mean km per day
  double day_km_long_run_sd = 0.0;         // lambda: the long-run sd of a day's km
  int km_per_day_dof = 0;                  // of km_per_day_se
  // The fleet's acceleration b per mm of wear (wear_acceleration.h; 0: a straight line), how
  // the clearance now and the rate above move with b and with the calendar trend gamma
  // (d c / d b = -g_c, d r / d b = -g_r; d c / d gamma = -h_c, d r / d gamma = -h_r), and the
  // covariance of (b, gamma) with its degrees of freedom.
  double acceleration_per_mm = 0.0;
  double clearance_per_acceleration = 0.0;  // mm^2
  double rate_per_acceleration = 0.0;       // mm^2 per km
  double clearance_per_trend = 0.0;         // mm day
  double rate_per_trend = 0.0;              // mm day per km
  double acceleration_se = 0.0;
  double trend_se = 0.0;
  double acceleration_trend_covariance = 0.0;
  int acceleration_dof = 0;
  // The rate to come's relative variance from the season the history has not seen
  // (season_to_come.h), at acceleration_dof degrees of freedom; 0: none.
  double season_variance = 0.0;
  // The season carried forward (season_to_come.h, seasonal_days): the fleet's trend gamma and
  // the last run's day less the history's km-weighted mean day; gamma 0: the mean season's.
  double season_trend_per_day = 0.0;
  double season_departure_days = 0.0;
  // The long-run relative variance of a day's wear per km (weekly_wear_rate.h; per day): the
  // mean rate over the D days to come scatters by rate_long_run_variance / D; 0: none.
  double rate_long_run_variance = 0.0;
  int rate_long_run_dof = 0;
};

// The 95 % interval.
LimitForecast forecast_limit(const ForecastInput& input, double limit_clearance_mm);

// At `level` (0 < level < 1); with dof 0 the rate interval given is used whatever the level.
LimitForecast forecast_limit(const ForecastInput& input, double limit_clearance_mm, double level);

// "YYYY-MM-DD" of a day count since 1970-01-01 (the fraction dropped); "after 9999-12-31" beyond
// that day (a rate barely above zero).
std::string date_of_day(double day);

}  // namespace flange::host
