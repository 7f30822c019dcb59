// SPDX-License-Identifier: MIT
// When a wheel reaches a clearance limit: the fitted line of its current flange (the segment
// since the last reprofiling) extended from its last run at the fitted rate. The interval comes
// from the rate's 95 % interval (the distance left at the fast and the slow end of it); days
// from distance at the locomotive's mean km per calendar day over its history (depot days
// included), which the interval does not widen.
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
  double rate_low_mm_per_km = 0.0;  // 95 % interval
  double rate_high_mm_per_km = 0.0;
  double km_per_day = 0.0;  // > 0 for days and dates
  double last_day = 0.0;    // days since 1970-01-01 of the last run
};

LimitForecast forecast_limit(const ForecastInput& input, double limit_clearance_mm);

// "YYYY-MM-DD" of a day count since 1970-01-01 (the fraction dropped); "after 9999-12-31" beyond
// that day (a rate barely above zero).
std::string date_of_day(double day);

}  // namespace flange::host
