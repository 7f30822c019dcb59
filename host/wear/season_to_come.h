// SPDX-License-Identifier: MIT
// The season to come in the dates' interval. The forecast runs on at the history's mean season
// (wear_acceleration.h: the fleet's calendar trend gamma is not carried forward), and the
// run-to-run and week-to-week scatter that make the rate's and the km's uncertainties are about
// the history's own days: neither says how the months to a limit, which the history has not
// seen, wear against its mean. What the history does say is how far its own season moved the
// rate: by gamma per day, so that at its last run the rate stood gamma (t_last - t_mean) off the
// mean season's (t_mean the km-weighted mean day the rate is taken at). The rate to come is given
// that departure as its relative standard deviation, either way (a season turns: carried forward
// as a shift it would run on past summer's peak), with gamma's own uncertainty: the relative
// variance of the rate to come is
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

}  // namespace flange::host
