// SPDX-License-Identifier: MIT
// The season to come, in the dates and in their interval. The line's rate is the history's mean
// season's (wear_acceleration.h: the fleet's calendar trend gamma is taken out of it), and the
// run-to-run and week-to-week scatter that make the rate's and the km's uncertainties are about
// the history's own days: neither says how the months to a limit, which the history has not
// seen, wear against its mean. What the history does say is how its own season moved the rate:
// by gamma per day about its km-weighted mean day t_mean.
//
// The date: a season is a cycle of kSeasonCycleDays, so the rate to come is the mean season's
// times 1 + A sin(omega (t - t_mean)), omega = 2 pi / kSeasonCycleDays, the cycle's sinusoid
// whose slope at t_mean is gamma (A = gamma / omega) and whose mean over the cycle is the
// history's mean season (seasonal_days). It rises on from a spring's history into the summer and
// turns after it, where a trend carried forward as a line would run on past summer's peak and the
// mean season alone misses the summer to come: on the second reality's development fleets (a
// March-June history, wear 1.5 % faster per degC) the mean season's dates came early, healthy
// wheels' warning dates most (the weeks after the history are the year's hottest).
//
// The interval: the sinusoid's phase is taken, not measured (t_mean at the cycle's crossing), so
// the departure the history saw at its last run, gamma (t_last - t_mean), stays the rate to come's
// relative standard deviation, either way, with gamma's own uncertainty:
//   v = (gamma^2 + se(gamma)^2) (t_last - t_mean)^2 (1 - span / kSeasonCycleDays),
// the last factor because a history of a whole cycle has seen every season and its mean season is
// the year's (v = 0 from a year of history on). It enters the km's and the days' relative
// variance (limit_forecast.h) at gamma's degrees of freedom.
#pragma once

#include <vector>

#include "wear_acceleration.h"
#include "wheel_history.h"

namespace flange::host {

// The season's cycle: a history this long has seen the year's mean season.
inline constexpr double kSeasonCycleDays = 365.25;

// The history's km-weighted mean day (each gap's km on the day it starts), as the fleet's trend
// is centred on (wear_acceleration.h); the last run's day when no km were run.
double km_weighted_mean_day(const std::vector<WearObservation>& runs);

// v above for a wheel with these runs (in time order); 0 when the fleet's trend is not estimated.
double season_to_come_variance(const FleetAcceleration& fleet,
                               const std::vector<WearObservation>& runs);

// The days T to come at which a flange wearing at the history's mean season would have run
// `flat_days` of that season's wear, when the season moves the rate by
// 1 + A sin(omega (t - t_mean)), omega = 2 pi / kSeasonCycleDays, A = gamma / omega: the
// sinusoid of the season's cycle whose slope at the history's mean day is the fleet's trend
// gamma (and whose mean over the cycle is the history's mean season). `departure_days` is
// t_last - t_mean. Solves int_0^T (1 + A sin(omega (departure + t))) dt = flat_days; flat_days
// itself when |A| >= 1 (a rate the sinusoid would stop) or gamma is 0.
double seasonal_days(double flat_days, double trend_per_day, double departure_days);

}  // namespace flange::host
