// SPDX-License-Identifier: MIT
#include "daily_distance.h"

#include <algorithm>
#include <cmath>

namespace flange::host {
namespace {

// The history's km day by day: each run's odometer step on its day, 0 on the days between.
std::vector<double> day_series(const std::vector<WearObservation>& runs, int days) {
  std::vector<double> km(static_cast<std::size_t>(days), 0.0);
  for (std::size_t k = 1; k < runs.size(); ++k) {
    const long day = std::lround(runs[k - 1].day - runs.front().day);
    const auto index = static_cast<std::size_t>(std::clamp(day, 0L, static_cast<long>(days) - 1));
    km[index] += runs[k].odometer_km - runs[k - 1].odometer_km;
  }
  return km;
}

// lambda, phi and the degrees of freedom from the whole weeks' means (see the header); nothing
// changed when there are too few weeks.
void from_weeks(DailyDistance& distance, const std::vector<double>& km) {
  const std::size_t weeks = km.size() / kRosterWeekDays;
  if (weeks < static_cast<std::size_t>(kMinWeeksForCorrelation)) return;
  const std::size_t first = km.size() - weeks * kRosterWeekDays;  // the oldest days left out
  std::vector<double> means(weeks, 0.0);
  for (std::size_t j = 0; j < weeks; ++j) {
    for (std::size_t d = 0; d < kRosterWeekDays; ++d) {
      means[j] += km[first + j * kRosterWeekDays + d] / kRosterWeekDays;
    }
  }
  double mean = 0.0;
  for (const double w : means) mean += w / static_cast<double>(weeks);
  double squares = 0.0, lagged = 0.0;
  for (std::size_t j = 0; j < weeks; ++j) {
    squares += (means[j] - mean) * (means[j] - mean);
    if (j > 0) lagged += (means[j] - mean) * (means[j - 1] - mean);
  }
  if (!(squares > 0.0)) return;
  const auto k = static_cast<double>(weeks);
  const double phi = std::clamp(lagged / squares, 0.0, kMaxWeekCorrelation);
  const double week_variance = squares / (k - 1.0);
  distance.long_run_sd = std::sqrt(kRosterWeekDays * week_variance * (1.0 + phi) / (1.0 - phi));
  distance.week_correlation = phi;
  const double effective_weeks = k * (1.0 - phi * phi) / (1.0 + phi * phi);
  distance.dof = std::max(1, static_cast<int>(std::floor(effective_weeks)) - 1);
}

}  // namespace

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
  distance.long_run_sd = distance.day_sd;
  distance.dof = static_cast<int>(std::lround(days)) - 1;
  from_weeks(distance, day_series(runs, static_cast<int>(std::lround(days))));
  distance.se = distance.long_run_sd / std::sqrt(days);
  return distance;
}

}  // namespace flange::host
