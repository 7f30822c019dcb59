// SPDX-License-Identifier: MIT
#include "limit_forecast.h"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <tuple>
#include <utility>

#include "wear_line_fit.h"

namespace flange::host {
namespace {

std::optional<double> km_at(double gap_mm, double rate_mm_per_km) {
  if (!(rate_mm_per_km > 0.0)) return std::nullopt;
  return gap_mm / rate_mm_per_km;
}

// Relative standard deviations of the distance left and of the days to it (see the header),
// and the degrees of freedom of the days' (Welch-Satterthwaite).
struct RelativeSpread {
  double km = 0.0, days = 0.0;
  double days_dof = 0.0;
};

RelativeSpread relative_spread(const ForecastInput& input, double gap_mm) {
  const double r = input.rate_mm_per_km;
  const double ratio = gap_mm / r;  // G / r = K
  const double km_variance = input.clearance_now_se_mm * input.clearance_now_se_mm +
                             ratio * ratio * input.rate_se_mm_per_km * input.rate_se_mm_per_km +
                             2.0 * ratio * input.clearance_rate_covariance;
  RelativeSpread spread;
  spread.km = std::sqrt(std::max(0.0, km_variance)) / gap_mm;
  if (input.km_per_day > 0.0) {
    const double mean_term = input.km_per_day_se / input.km_per_day;
    const double future_term =
        input.day_km_long_run_sd * input.day_km_long_run_sd / (input.km_per_day * ratio);
    const double line = spread.km * spread.km, mean = mean_term * mean_term;
    spread.days = std::sqrt(line + mean + future_term);
    const double parts =
        line * line / std::max(1, input.dof) + mean * mean / std::max(1, input.km_per_day_dof);
    spread.days_dof = parts > 0.0 ? std::pow(spread.days, 4.0) / parts : 1e9;
  }
  return spread;
}

// K / (1 + q s) and K / (1 - q s); the slow end unbounded when q s reaches 1.
std::pair<std::optional<double>, std::optional<double>> bounds(double value, double q_spread) {
  const std::optional<double> high =
      q_spread < 1.0 ? std::optional(value / (1.0 - q_spread)) : std::nullopt;
  return {value / (1.0 + q_spread), high};
}

int days_dof_of(const RelativeSpread& spread) {
  return static_cast<int>(std::min(1e6, std::max(1.0, std::floor(spread.days_dof))));
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
  return forecast_limit(input, limit_clearance_mm, 0.95);
}

LimitForecast forecast_limit(const ForecastInput& input, double limit_clearance_mm, double level) {
  LimitForecast forecast;
  forecast.limit_clearance_mm = limit_clearance_mm;
  const double gap_mm = std::max(0.0, limit_clearance_mm - input.clearance_now_mm);
  forecast.reached = gap_mm == 0.0;
  forecast.km = km_at(gap_mm, input.rate_mm_per_km);
  const bool spread_known = input.dof > 0 && forecast.km && !forecast.reached;
  const double q = spread_known ? t_quantile(level, input.dof) : 0.0;
  const RelativeSpread spread = spread_known ? relative_spread(input, gap_mm) : RelativeSpread{};
  const double q_days = spread_known ? t_quantile(level, days_dof_of(spread)) : 0.0;
  if (spread_known) {
    std::tie(forecast.km_low, forecast.km_high) = bounds(*forecast.km, q * spread.km);
  } else {
    forecast.km_low = km_at(gap_mm, input.rate_high_mm_per_km);
    forecast.km_high = km_at(gap_mm, input.rate_low_mm_per_km);
  }
  if (forecast.reached) forecast.km = forecast.km_low = forecast.km_high = 0.0;
  if (!(input.km_per_day > 0.0)) return forecast;
  const auto to_days = [&](const std::optional<double>& km) -> std::optional<double> {
    if (!km) return std::nullopt;
    return *km / input.km_per_day;
  };
  forecast.days = to_days(forecast.km);
  if (spread_known) {
    std::tie(forecast.days_low, forecast.days_high) = bounds(*forecast.days, q_days * spread.days);
  } else {
    forecast.days_low = to_days(forecast.km_low);
    forecast.days_high = to_days(forecast.km_high);
  }
  const auto to_date = [&](const std::optional<double>& days) {
    return days ? date_of_day(input.last_day + *days) : std::string();
  };
  forecast.date = to_date(forecast.days);
  forecast.date_low = to_date(forecast.days_low);
  forecast.date_high = to_date(forecast.days_high);
  return forecast;
}

}  // namespace flange::host
