// SPDX-License-Identifier: MIT
// The history's mean wear per km (history_mean_rate.h): the wear gained from the first run to the
// last over the km between, where the straight line's slope weighs the middle of the history most.
// Synthetic series over 120 days whose wear per km moves with the locomotive's duties (a rate
// factor held for one to four weeks at a time), with white scatter and a slow AR(1) part.
#include "history_mean_rate.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "moderated_spread.h"
#include "wear_line_fit.h"

namespace flange::host {
namespace {

constexpr double kRatePerKm = 0.05 / 1000.0;
constexpr int kDays = 120;

struct Duties {
  std::vector<double> factor;  // per day: the duty's wear per km over kRatePerKm
};

// A duty held for 7-28 days at a time, its factor drawn from [low, high].
Duties random_duties(std::mt19937& random, double low, double high) {
  std::uniform_real_distribution<double> factor(low, high);
  std::uniform_int_distribution<int> weeks(1, 4);
  Duties duties;
  while (static_cast<int>(duties.factor.size()) < kDays) {
    const double f = factor(random);
    for (int d = 0; d < 7 * weeks(random); ++d) duties.factor.push_back(f);
  }
  duties.factor.resize(kDays);
  return duties;
}

struct Series {
  WearSeries series;
  double true_rate = 0.0;  // per km: wear from the first run to the last over the km between
};

// A depot day with chance 0.15, 150-750 km on the others; a reprofiling on day 70 when
// `reprofiled`. Errors: white (sd 0.004 mm) plus AR(1) at 0.8 per day of sd `slow_sd` mm.
Series synthetic_series(std::mt19937& random, const Duties& duties, double slow_sd,
                        bool reprofiled) {
  std::uniform_real_distribution<double> unit(0.0, 1.0), km_of_day(150.0, 750.0);
  std::normal_distribution<double> white(0.0, 0.004), stationary(0.0, slow_sd);
  std::normal_distribution<double> shock(0.0, slow_sd * std::sqrt(1.0 - 0.8 * 0.8));
  Series out;
  double odometer = 0.0, slow = stationary(random), wear = 2.0, worn = 0.0;
  double first_km = 0.0, last_km = 0.0, worn_at_first = 0.0, worn_at_last = 0.0;
  for (int day = 0; day < kDays; ++day) {
    slow = 0.8 * slow + shock(random);
    if (reprofiled && day == 70) wear = 0.5;
    const double km = km_of_day(random);
    if (unit(random) >= 0.15) {
      if (out.series.km.empty()) {
        first_km = odometer;
        worn_at_first = worn;
      }
      last_km = odometer;
      worn_at_last = worn;
      out.series.km.push_back(odometer);
      out.series.day.push_back(20454.0 + day + 0.25);
      out.series.y.push_back(2.0 + wear + slow + white(random));
      out.series.segment.push_back(reprofiled && day >= 70 ? 1 : 0);
    }
    odometer += km;
    const double wear_today = kRatePerKm * duties.factor[static_cast<std::size_t>(day)] * km;
    wear += wear_today;
    worn += wear_today;
  }
  out.true_rate = (worn_at_last - worn_at_first) / (last_km - first_km);
  return out;
}

TEST(HistoryMeanRate, IsTheLinesSlopeWhenTheRateStaysPut) {
  std::mt19937 random(3);
  Duties steady;
  steady.factor.assign(kDays, 1.0);
  const Series s = synthetic_series(random, steady, 0.0, false);
  const std::optional<HistoryMeanFit> history = history_mean_fit(s.series);
  ASSERT_TRUE(history.has_value());
  EXPECT_EQ(history->pieces, 3);
  const WearLineFit line = fit_wear_line(s.series, std::nullopt);
  EXPECT_NEAR(history->rate_mm_per_km, s.true_rate, 3.0 * history->rate_se);
  EXPECT_NEAR(history->rate_mm_per_km, line.rate_mm_per_km, 2.0 * history->rate_se);
  // The rise over three pieces rests on the ends more than the slope does: wider, not wildly.
  EXPECT_GT(history->rate_se, line.rate_se);
  EXPECT_LT(history->rate_se, 3.0 * line.rate_se);
  EXPECT_EQ(history->own_spread.blocks, 3 * kBlocksPerPiece);
}

// Duties that wore the flange fast at both ends of the history and slowly in its middle: the
// line's slope reads low, the history's rise does not.
TEST(HistoryMeanRate, FollowsDutiesTheLinesSlopeReadsLow) {
  std::mt19937 random(5);
  Duties duties;
  for (int day = 0; day < kDays; ++day) {
    duties.factor.push_back(day < 30 || day >= 90 ? 1.5 : 0.6);
  }
  const Series s = synthetic_series(random, duties, 0.0, false);
  const std::optional<HistoryMeanFit> history = history_mean_fit(s.series);
  ASSERT_TRUE(history.has_value());
  const WearLineFit line = fit_wear_line(s.series, std::nullopt);
  const double line_error = std::abs(line.rate_mm_per_km / s.true_rate - 1.0);
  const double history_error = std::abs(history->rate_mm_per_km / s.true_rate - 1.0);
  EXPECT_GT(line_error, 0.07);
  EXPECT_LT(history_error, 0.5 * line_error);
}

// Four runs, two at each end of two months: one stretch left out leaves two runs for two
// parameters, so there is no jackknife, and no history fit that would claim the runs' scatter
// alone.
TEST(HistoryMeanRate, NoneWithoutAJackknife) {
  WearSeries series;
  for (const double day : {0.0, 1.0, 58.0, 60.0}) {
    series.day.push_back(20454.0 + day);
    series.km.push_back(400.0 * day);
    series.y.push_back(2.0 + 0.00005 * 400.0 * day + (day == 1.0 ? 0.001 : 0.0));
    series.segment.push_back(0);
  }
  EXPECT_FALSE(history_mean_fit(series).has_value());
  series.day.insert(series.day.begin() + 2, {20454.0 + 25.0, 20454.0 + 30.0});
  series.km.insert(series.km.begin() + 2, {10000.0, 12000.0});
  series.y.insert(series.y.begin() + 2, {2.5, 2.6});
  series.segment.insert(series.segment.begin() + 2, {0, 0});
  EXPECT_TRUE(history_mean_fit(series).has_value());
}

struct Held {
  double history = 0.0, line = 0.0;
};

// How often each rate's interval at `level` (its jackknife moderated by the fleet's) holds the
// history's true mean rate, over `fleets` fleets of 30 series, each fleet's wheels on one
// locomotive's duties (factors 0.6-1.5), each wheel's slow sd 0.008 mm times exp(N(0, 0.3)).
Held coverage(bool reprofiled, double level, int fleets, std::uint32_t seed) {
  std::mt19937 random(seed);
  std::normal_distribution<double> log_size(0.0, 0.3);
  int history_held = 0, line_held = 0, n = 0;
  for (int f = 0; f < fleets; ++f) {
    const Duties duties = random_duties(random, 0.6, 1.5);
    std::vector<Series> series;
    std::vector<HistoryMeanFit> histories;
    std::vector<WearLineFit> lines;
    std::vector<SerialSpread> history_own, line_own;
    for (int w = 0; w < 30; ++w) {
      series.push_back(
          synthetic_series(random, duties, 0.008 * std::exp(log_size(random)), reprofiled));
      histories.push_back(*history_mean_fit(series.back().series));
      lines.push_back(fit_wear_line(series.back().series, std::nullopt));
      history_own.push_back(histories.back().own_spread);
      line_own.push_back(jackknife_rate(series.back().series, std::nullopt, 1, lines.back()));
    }
    const InflationPrior history_prior = inflation_prior(history_own);
    const InflationPrior line_prior = inflation_prior(line_own);
    for (std::size_t w = 0; w < series.size(); ++w, ++n) {
      const SerialSpread h = moderated_spread(history_own[w], history_prior, histories[w].rate_se);
      const SerialSpread l = moderated_spread(line_own[w], line_prior, lines[w].rate_se);
      const double truth = series[w].true_rate;
      history_held +=
          std::abs(histories[w].rate_mm_per_km - truth) <= t_quantile(level, h.dof) * h.rate_se ? 1
                                                                                                : 0;
      line_held +=
          std::abs(lines[w].rate_mm_per_km - truth) <= t_quantile(level, l.dof) * l.rate_se ? 1 : 0;
    }
  }
  return {static_cast<double>(history_held) / n, static_cast<double>(line_held) / n};
}

// 1200 series per figure (a binomial standard error of 0.6 % at 95 %, 1.2 % at 80 %; a fleet's
// wheels share its duties and prior, so the figures scatter somewhat more). On these series the
// jackknife leans wide (98-100 % at 95 %, 86-89 % at 80 %; on white scatter alone 98 / 90 %, the
// line's 98 / 84 %): a stretch left out near either end takes much of the odometer's leverage with
// it. The line's interval holds its slope, not the history's mean, and falls short at 80 % on a
// flange's history that the duties bend.
TEST(HistoryMeanRate, HoldsAtLeastItsLevelWhenTheDutiesMoveTheRate) {
  for (const bool reprofiled : {false, true}) {
    const Held at95 = coverage(reprofiled, 0.95, 40, 21);
    const Held at80 = coverage(reprofiled, 0.80, 40, 22);
    EXPECT_GT(at95.history, 0.95) << "reprofiled " << reprofiled;
    EXPECT_GT(at80.history, 0.80) << "reprofiled " << reprofiled;
    EXPECT_LT(at80.history, 0.93) << "reprofiled " << reprofiled;
    if (!reprofiled) {
      EXPECT_LT(at80.line, 0.80);
    }
  }
}

}  // namespace
}  // namespace flange::host
