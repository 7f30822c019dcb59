// SPDX-License-Identifier: MIT
#include "limit_forecast.h"

#include <fmt/format.h>

#include <chrono>
#include <cmath>

namespace flange::host {
namespace {

std::optional<double> km_at(double gap_mm, double rate_mm_per_km) {
  if (!(rate_mm_per_km > 0.0)) return std::nullopt;
  return gap_mm / rate_mm_per_km;
}

}  // namespace

std::string date_of_day(double day) {
  using namespace std::chrono;
  // A rate barely above zero puts the limit millions of years away, past what a date holds.
  constexpr double kLastDay = 2932896.0;  // 9999-12-31
  if (!(day <= kLastDay)) return "after 9999-12-31";
  const year_month_day date{sys_days{days{static_cast<int>(std::floor(day))}}};
  return fmt::format("{:04d}-{:02d}-{:02d}", static_cast<int>(date.year()),
                     static_cast<unsigned>(date.month()), static_cast<unsigned>(date.day()));
}

LimitForecast forecast_limit(const ForecastInput& input, double limit_clearance_mm) {
  LimitForecast forecast;
  forecast.limit_clearance_mm = limit_clearance_mm;
  const double gap_mm = std::max(0.0, limit_clearance_mm - input.clearance_now_mm);
  forecast.reached = gap_mm == 0.0;
  forecast.km = km_at(gap_mm, input.rate_mm_per_km);
  forecast.km_low = km_at(gap_mm, input.rate_high_mm_per_km);
  forecast.km_high = km_at(gap_mm, input.rate_low_mm_per_km);
  if (forecast.reached) forecast.km = forecast.km_low = forecast.km_high = 0.0;
  if (!(input.km_per_day > 0.0)) return forecast;
  const auto to_days = [&](const std::optional<double>& km) -> std::optional<double> {
    if (!km) return std::nullopt;
    return *km / input.km_per_day;
  };
  forecast.days = to_days(forecast.km);
  forecast.days_low = to_days(forecast.km_low);
  forecast.days_high = to_days(forecast.km_high);
  const auto to_date = [&](const std::optional<double>& days) {
    return days ? date_of_day(input.last_day + *days) : std::string();
  };
  forecast.date = to_date(forecast.days);
  forecast.date_low = to_date(forecast.days_low);
  forecast.date_high = to_date(forecast.days_high);
  return forecast;
}

}  // namespace flange::host
