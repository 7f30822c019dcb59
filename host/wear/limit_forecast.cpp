// SPDX-License-Identifier: MIT
#include "limit_forecast.h"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <tuple>
#include <utility>

#include "season_to_come.h"
#include "wear_line_fit.h"

namespace flange::host {
namespace {

// (1 - exp(-b G)) / b: the wear-to-distance factor (G as b -> 0), and its derivative in b.
double accelerated_gap(double gap_mm, double b) {
  const double x = b * gap_mm;
  if (std::abs(x) < 1e-8) return gap_mm * (1.0 - x / 2.0);
  return -std::expm1(-x) / b;
}

double accelerated_gap_per_b(double gap_mm, double b) {
  const double x = b * gap_mm;
  if (std::abs(x) < 1e-6) return -gap_mm * gap_mm * (0.5 - x / 3.0);
  return (x * std::exp(-x) + std::expm1(-x)) / (b * b);
}

std::optional<double> km_at(double gap_mm, double rate_mm_per_km, double b) {
  if (!(rate_mm_per_km > 0.0)) return std::nullopt;
  return accelerated_gap(gap_mm, b) / rate_mm_per_km;
}

// Relative standard deviations of the distance left and of the days to it (see the header),
// and the degrees of freedom of each (Welch-Satterthwaite).
struct RelativeSpread {
  double km = 0.0, days = 0.0;
  double km_dof = 0.0, days_dof = 0.0;
};

RelativeSpread relative_spread(const ForecastInput& input, double gap_mm) {
  const double r = input.rate_mm_per_km;
  const double b = input.acceleration_per_mm;
  const double km = accelerated_gap(gap_mm, b) / r;
  // K's derivatives in the clearance now, the rate and b (through all three).
  const double per_clearance = -std::exp(-b * gap_mm) / r;
  const double per_rate = -km / r;
  const double per_b = accelerated_gap_per_b(gap_mm, b) / r +
                       per_clearance * input.clearance_per_acceleration +
                       per_rate * input.rate_per_acceleration;
  const double per_trend =
      per_clearance * input.clearance_per_trend + per_rate * input.rate_per_trend;
  const double line_variance =
      per_clearance * per_clearance * input.clearance_now_se_mm * input.clearance_now_se_mm +
      per_rate * per_rate * input.rate_se_mm_per_km * input.rate_se_mm_per_km +
      2.0 * per_clearance * per_rate * input.clearance_rate_covariance;
  const double line = std::max(0.0, line_variance) / (km * km);
  const double acceleration =
      std::max(0.0, per_b * per_b * input.acceleration_se * input.acceleration_se +
                        per_trend * per_trend * input.trend_se * input.trend_se +
                        2.0 * per_b * per_trend * input.acceleration_trend_covariance) /
      (km * km);
  // The fleet's terms: b and gamma in the line, the season to come; at the fleet's dof. The
  // duties to come over the days to K (when they are known).
  const double fleet = acceleration + std::max(0.0, input.season_variance);
  const double duty = input.km_per_day > 0.0
                          ? std::max(0.0, input.rate_long_run_variance) * input.km_per_day / km
                          : 0.0;
  RelativeSpread spread;
  spread.km = std::sqrt(line + fleet + duty);
  const double line_part = line * line / std::max(1, input.dof);
  const double acceleration_part =
      fleet > 0.0 ? fleet * fleet / std::max(1, input.acceleration_dof) : 0.0;
  const double duty_part = duty > 0.0 ? duty * duty / std::max(1, input.rate_long_run_dof) : 0.0;
  const double km_parts = line_part + acceleration_part + duty_part;
  spread.km_dof = (fleet > 0.0 || duty > 0.0) && km_parts > 0.0
                      ? std::pow(spread.km, 4.0) / km_parts
                      : static_cast<double>(input.dof);
  if (input.km_per_day > 0.0) {
    const double mean_term = input.km_per_day_se / input.km_per_day;
    const double future_term =
        input.day_km_long_run_sd * input.day_km_long_run_sd / (input.km_per_day * km);
    const double mean = mean_term * mean_term;
    spread.days = std::sqrt(line + fleet + duty + mean + future_term);
    const double parts = km_parts + mean * mean / std::max(1, input.km_per_day_dof);
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

int dof_of(double welch_satterthwaite) {
  return static_cast<int>(std::min(1e6, std::max(1.0, std::floor(welch_satterthwaite))));
}

// The days to the limit at the history's mean season (K / mu, with the days' interval at
// q sd T / T when known, else the km's bounds'), then each as the season to come moves the rate
// (seasonal_days), and the km with them: mu times the days at the mean season they make.
void with_days(LimitForecast& forecast, const ForecastInput& input,
               std::optional<double> q_days_spread) {
  const double mu = input.km_per_day;
  const auto flat_days = [&](const std::optional<double>& km) -> std::optional<double> {
    if (!km) return std::nullopt;
    return *km / mu;
  };
  const std::optional<double> days = flat_days(forecast.km);
  std::optional<double> days_low = flat_days(forecast.km_low),
                        days_high = flat_days(forecast.km_high);
  if (q_days_spread) std::tie(days_low, days_high) = bounds(*days, *q_days_spread);
  const auto seasonal = [&](const std::optional<double>& flat) -> std::optional<double> {
    if (!flat) return std::nullopt;
    return seasonal_days(*flat, input.season_trend_per_day, input.season_departure_days);
  };
  for (std::optional<double>* km : {&forecast.km, &forecast.km_low, &forecast.km_high}) {
    if (*km) *km = mu * *seasonal(flat_days(*km));
  }
  forecast.days = seasonal(days);
  forecast.days_low = seasonal(days_low);
  forecast.days_high = seasonal(days_high);
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
  const double b = input.acceleration_per_mm;
  forecast.km = km_at(gap_mm, input.rate_mm_per_km, b);
  const bool spread_known = input.dof > 0 && forecast.km && !forecast.reached;
  const RelativeSpread spread = spread_known ? relative_spread(input, gap_mm) : RelativeSpread{};
  const double q = spread_known ? t_quantile(level, dof_of(spread.km_dof)) : 0.0;
  const double q_days = spread_known ? t_quantile(level, dof_of(spread.days_dof)) : 0.0;
  if (spread_known) {
    std::tie(forecast.km_low, forecast.km_high) = bounds(*forecast.km, q * spread.km);
  } else {
    forecast.km_low = km_at(gap_mm, input.rate_high_mm_per_km, b);
    forecast.km_high = km_at(gap_mm, input.rate_low_mm_per_km, b);
  }
  if (forecast.reached) forecast.km = forecast.km_low = forecast.km_high = 0.0;
  if (!(input.km_per_day > 0.0)) return forecast;
  with_days(forecast, input, spread_known ? std::optional(q_days * spread.days) : std::nullopt);
  const auto to_date = [&](const std::optional<double>& days) {
    return days ? date_of_day(input.last_day + *days) : std::string();
  };
  forecast.date = to_date(forecast.days);
  forecast.date_low = to_date(forecast.days_low);
  forecast.date_high = to_date(forecast.days_high);
  return forecast;
}

}  // namespace flange::host
