// SPDX-License-Identifier: MIT
#include "season_to_come.h"

#include <algorithm>
#include <cmath>
#include <numbers>

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

double seasonal_days(double flat_days, double trend_per_day, double departure_days) {
  const double omega = 2.0 * std::numbers::pi / kSeasonCycleDays;
  const double amplitude = trend_per_day / omega;
  if (!(std::abs(amplitude) < 1.0) || amplitude == 0.0 || !(flat_days > 0.0) ||
      !std::isfinite(flat_days)) {
    return flat_days;
  }
  const double start = std::cos(omega * departure_days);
  const auto season_days = [&](double t) {
    return t + amplitude / omega * (start - std::cos(omega * (departure_days + t)));
  };
  // season_days rises at 1 +- |A|: the root lies between these.
  double low = flat_days / (1.0 + std::abs(amplitude));
  double high = flat_days / (1.0 - std::abs(amplitude));
  for (int step = 0; step < 100 && high - low > 1e-9 * high; ++step) {
    const double middle = 0.5 * (low + high);
    (season_days(middle) < flat_days ? low : high) = middle;
  }
  return 0.5 * (low + high);
}

}  // namespace flange::host
