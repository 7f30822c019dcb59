// SPDX-License-Identifier: MIT
#include "weekly_wear_rate.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>

namespace flange::host {
namespace {

struct RunKm {
  double day = 0.0, odometer_km = 0.0;
  std::vector<double> wear_km;  // each wheel's u
};

// Per run (by id): its day, odometer and every wheel's wear in km at its own rate.
std::map<std::int64_t, RunKm> wear_in_km(const std::vector<WeeklyWearWheel>& wheels) {
  std::map<std::int64_t, RunKm> runs;
  for (const WeeklyWearWheel& wheel : wheels) {
    const WearLineFit& fit = *wheel.fit;
    if (!(fit.rate_mm_per_km > 0.0) || fit.drift_onset_day) continue;
    for (std::size_t k = 0; k < wheel.runs->size(); ++k) {
      const WearObservation& run = (*wheel.runs)[k];
      const auto segment = static_cast<std::size_t>((*wheel.segment)[k]);
      RunKm& at = runs[run.run_id];
      at.day = run.day;
      at.odometer_km = run.odometer_km;
      at.wear_km.push_back((run.clearance_mm - fit.intercepts_mm[segment]) / fit.rate_mm_per_km +
                           fit.km0);
    }
  }
  return runs;
}

double median(std::vector<double> values) {
  const std::size_t half = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(half),
                   values.end());
  const double upper = values[half];
  if (values.size() % 2 == 1) return upper;
  return (*std::max_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(half)) +
          upper) /
         2.0;
}

struct WeekRate {
  double rate = 0.0;
  double variance = 0.0;  // the slope's own, from its residuals
};

// Each whole week's least-squares slope of the median wear in km on the odometer, oldest first.
std::vector<WeekRate> week_rates(const std::map<std::int64_t, RunKm>& runs) {
  double last = -1e300;
  for (const auto& [id, run] : runs) last = std::max(last, run.day);
  std::map<long, std::vector<std::pair<double, double>>> weeks;  // weeks back -> (km, u)
  for (const auto& [id, run] : runs) {
    const auto back = static_cast<long>(std::floor((last - run.day) / kRosterWeekDays));
    weeks[back].emplace_back(run.odometer_km, median(run.wear_km));
  }
  std::vector<WeekRate> rates;
  for (auto week = weeks.rbegin(); week != weeks.rend(); ++week) {
    const auto& points = week->second;
    const auto n = static_cast<double>(points.size());
    if (points.size() < static_cast<std::size_t>(kMinRunsPerWeek)) continue;
    double mean_km = 0.0, mean_u = 0.0;
    for (const auto& [km, u] : points) {
      mean_km += km / n;
      mean_u += u / n;
    }
    double kk = 0.0, ku = 0.0, uu = 0.0;
    for (const auto& [km, u] : points) {
      kk += (km - mean_km) * (km - mean_km);
      ku += (km - mean_km) * (u - mean_u);
      uu += (u - mean_u) * (u - mean_u);
    }
    if (!(kk > 0.0)) continue;
    const double slope = ku / kk;
    const double rss = std::max(0.0, uu - slope * ku);
    rates.push_back({slope, rss / (n - 2.0) / kk});
  }
  return rates;
}

}  // namespace

WeeklyWearRate weekly_wear_rate(const std::vector<WeeklyWearWheel>& wheels) {
  WeeklyWearRate result;
  const std::vector<WeekRate> rates = week_rates(wear_in_km(wheels));
  result.weeks = static_cast<int>(rates.size());
  if (result.weeks < kMinWeeksForCorrelation) return result;
  const auto k = static_cast<double>(rates.size());
  double mean = 0.0, scatter = 0.0;
  for (const WeekRate& week : rates) {
    mean += week.rate / k;
    scatter += week.variance / k;
  }
  double squares = 0.0, lagged = 0.0;
  for (std::size_t j = 0; j < rates.size(); ++j) {
    squares += (rates[j].rate - mean) * (rates[j].rate - mean);
    if (j > 0) lagged += (rates[j].rate - mean) * (rates[j - 1].rate - mean);
  }
  const double duty_variance = squares / (k - 1.0) - scatter;
  if (!(duty_variance > 0.0)) return result;
  const double phi = std::clamp(lagged / (k - 1.0) / duty_variance, 0.0, kMaxWeekCorrelation);
  result.week_correlation = phi;
  result.long_run_variance = kRosterWeekDays * duty_variance * (1.0 + phi) / (1.0 - phi);
  const double effective_weeks = k * (1.0 - phi * phi) / (1.0 + phi * phi);
  result.dof = std::max(1, static_cast<int>(std::floor(effective_weeks)) - 1);
  return result;
}

}  // namespace flange::host
