// SPDX-License-Identifier: MIT
#include "season_to_come.h"

#include <algorithm>

namespace flange::host {

double km_weighted_mean_day(const std::vector<WearObservation>& runs) {
  double km_days = 0.0, km_run = 0.0;
  for (std::size_t k = 0; k + 1 < runs.size(); ++k) {
    const double km = runs[k + 1].odometer_km - runs[k].odometer_km;
    km_days += runs[k].day * km;
    km_run += km;
  }
  return km_run > 0.0 ? km_days / km_run : runs.back().day;
}

double season_to_come_variance(const FleetAcceleration& fleet,
                               const std::vector<WearObservation>& runs) {
  if (fleet.dof == 0 || runs.size() < 2) return 0.0;
  const double departure_days = runs.back().day - km_weighted_mean_day(runs);
  const double span_days = runs.back().day - runs.front().day;
  const double unseen = std::max(0.0, 1.0 - span_days / kSeasonCycleDays);
  const double trend_square = fleet.trend * fleet.trend + fleet.trend_se * fleet.trend_se;
  return trend_square * departure_days * departure_days * unseen;
}

}  // namespace flange::host
