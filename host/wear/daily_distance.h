// SPDX-License-Identifier: MIT
// How far a locomotive runs per calendar day, from the odometer at its runs: the mean (depot days
// included), its standard error and how much one day's km scatters about it. A locomotive
// records at the start of every day it runs (the fleet scenario does, and so does a board that
// records at each start of service), so a day without a run is a day in the depot: the odometer's
// step from one run to the next is that run's day's km, and the days between ran 0 km. Over the
// history's days X_d: mu = sum X / days, sigma^2 = sum (X_d - mu)^2 / (days - 1),
// se mu = sigma / sqrt(days), the days taken as independent. The forecast's days and their
// interval are made from these (limit_forecast.h).
#pragma once

#include <vector>

#include "wheel_history.h"

namespace flange::host {

struct DailyDistance {
  double km_per_day = 0.0;  // mu; 0 when the runs span no time
  double se = 0.0;          // of mu
  double day_sd = 0.0;      // sigma: one day's km about mu
  int dof = 0;              // sigma's degrees of freedom: the days less one
};

// `runs` in time order. Fewer than two gaps give the mean alone (se and sigma 0).
DailyDistance daily_distance(const std::vector<WearObservation>& runs);

}  // namespace flange::host
