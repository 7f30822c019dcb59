// SPDX-License-Identifier: MIT
// The rate to come in the dates' interval: the season the history has not seen
// (season_to_come.h) and a locomotive's duties from week to week (weekly_wear_rate.h), each from
// what the history shows, and each widening the forecast's interval (limit_forecast.h); and the
// season carried forward in the dates (seasonal_days).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "limit_forecast.h"
#include "season_to_come.h"
#include "wear_line_fit.h"
#include "weekly_wear_rate.h"

namespace flange::host {
namespace {

constexpr double kFirstDay = 20454.0;

// A run every day at 400 km per day over `days` days.
std::vector<WearObservation> daily_runs(int days) {
  std::vector<WearObservation> runs;
  for (int day = 0; day < days; ++day) {
    WearObservation run;
    run.run_id = day;
    run.day = kFirstDay + day;
    run.odometer_km = 400.0 * day;
    runs.push_back(run);
  }
  return runs;
}

ForecastInput plain_input() {
  ForecastInput input{5.0, 0.05e-3, 0.045e-3, 0.055e-3, 400.0, kFirstDay + 119.0};
  input.clearance_now_se_mm = 0.01;
  input.rate_se_mm_per_km = 0.0025e-3;
  input.dof = 8;
  input.km_per_day_se = 5.0;
  input.day_km_long_run_sd = 100.0;
  input.km_per_day_dof = 30;
  return input;
}

TEST(ForecastSeasonToCome, TheSeasonSeenInTheHistoryWidensTheDatesUntilAYearOfIt) {
  FleetAcceleration fleet;
  fleet.trend = 0.002;
  fleet.trend_se = 0.0005;
  fleet.dof = 10;
  // 120 days at a steady 400 km: the km-weighted mean day is day 59, the last run day 119.
  const std::vector<WearObservation> runs = daily_runs(120);
  EXPECT_NEAR(km_weighted_mean_day(runs), kFirstDay + 59.0, 1e-9);
  const double expected =
      (0.002 * 0.002 + 0.0005 * 0.0005) * 60.0 * 60.0 * (1.0 - 119.0 / kSeasonCycleDays);
  EXPECT_NEAR(season_to_come_variance(fleet, runs), expected, 1e-12);
  // A history of a whole cycle has seen the year's mean season; no trend estimated: nothing.
  EXPECT_EQ(season_to_come_variance(fleet, daily_runs(400)), 0.0);
  fleet.dof = 0;
  EXPECT_EQ(season_to_come_variance(fleet, runs), 0.0);

  ForecastInput input = plain_input();
  const LimitForecast without = forecast_limit(input, 8.0);
  input.season_variance = expected;
  input.acceleration_dof = 10;
  const LimitForecast with = forecast_limit(input, 8.0);
  EXPECT_NEAR(*with.days, *without.days, 1e-9 * *without.days);  // the date stays
  EXPECT_LT(*with.days_low, *without.days_low);
  EXPECT_GT(*with.days_high, *without.days_high);
  EXPECT_LT(*with.km_low, *without.km_low);
}

// The season carried forward: the cycle's sinusoid whose slope at the history's mean day is the
// fleet's trend. With the rate rising at the last run (60 days past the mean day, gamma 0.002 per
// day: A = 0.116) the mean season's 100 days of wear come sooner; over a whole cycle the season
// averages out; the wear over the days found is the mean season's; a trend the sinusoid cannot
// hold with a positive rate, or none, leaves the mean season's days.
TEST(ForecastSeasonToCome, TheSeasonIsCarriedForwardAsTheCyclesSinusoid) {
  const double omega = 2.0 * std::acos(-1.0) / kSeasonCycleDays;
  const double gamma = 0.002, departure = 60.0, amplitude = gamma / omega;
  const double days = seasonal_days(100.0, gamma, departure);
  EXPECT_LT(days, 100.0 / 1.05);
  double worn = 0.0;  // int_0^days (1 + A sin(omega (departure + t))) dt, by the midpoint rule
  const int steps = 100000;
  for (int k = 0; k < steps; ++k) {
    const double t = (k + 0.5) * days / steps;
    worn += (1.0 + amplitude * std::sin(omega * (departure + t))) * days / steps;
  }
  EXPECT_NEAR(worn, 100.0, 1e-6);
  EXPECT_NEAR(seasonal_days(kSeasonCycleDays, gamma, departure), kSeasonCycleDays, 1e-6);
  EXPECT_GT(seasonal_days(100.0, gamma, -departure), 100.0);  // a rate falling at the last run
  EXPECT_EQ(seasonal_days(100.0, 0.0, departure), 100.0);
  EXPECT_EQ(seasonal_days(100.0, 1.2 * omega, departure), 100.0);

  // In the forecast: the days, their bounds and the km as the season moves the rate.
  ForecastInput input = plain_input();
  const LimitForecast mean_season = forecast_limit(input, 8.0);
  input.season_trend_per_day = gamma;
  input.season_departure_days = departure;
  const LimitForecast seasonal = forecast_limit(input, 8.0);
  EXPECT_NEAR(*seasonal.days, seasonal_days(*mean_season.days, gamma, departure), 1e-9);
  EXPECT_NEAR(*seasonal.days_low, seasonal_days(*mean_season.days_low, gamma, departure), 1e-9);
  EXPECT_NEAR(*seasonal.days_high, seasonal_days(*mean_season.days_high, gamma, departure), 1e-9);
  EXPECT_NEAR(*seasonal.km, input.km_per_day * *seasonal.days, 1e-6);
  EXPECT_LT(*seasonal.days, *mean_season.days);
}

// Six wheels of one locomotive over 16 weeks, a run every day at 400 km, each wheel its own rate;
// the locomotive's duty multiplies them all by duty[week]; noise_mm of white scatter per run.
WeeklyWearRate duty_estimate(const std::vector<double>& duty, double noise_mm,
                                           std::uint32_t seed) {
  std::mt19937 random(seed);
  std::normal_distribution<double> scatter(0.0, noise_mm);
  const int days = static_cast<int>(duty.size()) * 7;
  const std::vector<WearObservation> base = daily_runs(days);
  std::vector<std::vector<WearObservation>> runs;
  std::vector<std::vector<int>> segments;
  std::vector<WearLineFit> fits;
  for (int wheel = 0; wheel < 6; ++wheel) {
    const double rate = (0.04 + 0.01 * wheel) / 1000.0;
    std::vector<WearObservation> own = base;
    WearSeries series;
    double wear = 1.0;
    for (int day = 0; day < days; ++day) {
      own[static_cast<std::size_t>(day)].clearance_mm = 2.0 + wear + scatter(random);
      wear += rate * duty[static_cast<std::size_t>(day / 7)] * 400.0;
      series.km.push_back(own[static_cast<std::size_t>(day)].odometer_km);
      series.day.push_back(own[static_cast<std::size_t>(day)].day);
      series.y.push_back(own[static_cast<std::size_t>(day)].clearance_mm);
      series.segment.push_back(0);
    }
    runs.push_back(own);
    segments.push_back(series.segment);
    fits.push_back(fit_wear_line(series, std::nullopt));
  }
  std::vector<WeeklyWearWheel> wheels;
  for (std::size_t w = 0; w < fits.size(); ++w) wheels.push_back({&runs[w], &segments[w], &fits[w]});
  return weekly_wear_rate(wheels);
}

TEST(WeeklyWearRate, ADutyChangingFromWeekToWeekWidensTheDatesAndASteadyOneDoesNot) {
  // Two weeks fast, two slow, and so on: 1.3 and 0.7 of the mean, var 0.09 (16 / 15 of it over
  // the sample), lag-1 autocorrelation about 0: lambda_R^2 = 7 x 0.096 = 0.67 per day.
  std::vector<double> duty;
  for (int week = 0; week < 16; ++week) duty.push_back(week % 4 < 2 ? 1.3 : 0.7);
  const WeeklyWearRate changing = duty_estimate(duty, 0.002, 1);
  EXPECT_EQ(changing.weeks, 16);
  EXPECT_NEAR(changing.long_run_variance, 7.0 * 0.09 * 16.0 / 15.0, 0.1);
  EXPECT_GT(changing.dof, 0);
  // A steady duty: the weeks' slopes scatter by the runs' own noise alone, which is taken away.
  const WeeklyWearRate steady = duty_estimate(std::vector<double>(16, 1.0), 0.01, 2);
  EXPECT_LT(steady.long_run_variance, 0.01);
  // Too few weeks: none.
  EXPECT_EQ(duty_estimate(std::vector<double>(6, 1.0), 0.002, 3).long_run_variance, 0.0);

  ForecastInput input = plain_input();
  const LimitForecast without = forecast_limit(input, 8.0);
  input.rate_long_run_variance = changing.long_run_variance;
  input.rate_long_run_dof = changing.dof;
  const LimitForecast with = forecast_limit(input, 8.0);
  EXPECT_NEAR(*with.days, *without.days, 1e-9 * *without.days);
  EXPECT_LT(*with.days_low, *without.days_low);
  EXPECT_GT(*with.days_high, *without.days_high);
  // 0.67 / 150 days, against the line's (0.05)^2 and the km's: a visible share of the spread.
  const double spread_with = *with.days / *with.days_low - 1.0;
  const double spread_without = *without.days / *without.days_low - 1.0;
  EXPECT_GT(spread_with, 1.2 * spread_without);
}

}  // namespace
}  // namespace flange::host
