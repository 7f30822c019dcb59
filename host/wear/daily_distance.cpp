// SPDX-License-Identifier: MIT
#include "daily_distance.h"

#include <algorithm>
#include <cmath>

namespace flange::host {

DailyDistance daily_distance(const std::vector<WearObservation>& runs) {
  DailyDistance distance;
  if (runs.size() < 2) return distance;
  const double days = runs.back().day - runs.front().day;
  if (!(days > 0.0)) return distance;
  distance.km_per_day = (runs.back().odometer_km - runs.front().odometer_km) / days;
  double squares = 0.0;
  for (std::size_t k = 1; k < runs.size(); ++k) {
    const double gap_days = std::round(runs[k].day - runs[k - 1].day);
    const double step_km = runs[k].odometer_km - runs[k - 1].odometer_km;
    const double idle_days = std::max(0.0, gap_days - 1.0);  // in the depot: 0 km each
    squares += (step_km - distance.km_per_day) * (step_km - distance.km_per_day) +
               idle_days * distance.km_per_day * distance.km_per_day;
  }
  if (days < 2.0) return distance;
  distance.day_sd = std::sqrt(squares / (days - 1.0));
  distance.se = distance.day_sd / std::sqrt(days);
  distance.dof = static_cast<int>(std::lround(days)) - 1;
  return distance;
}

}  // namespace flange::host
