// SPDX-License-Identifier: MIT
// The wear line's intervals on synthetic series with a known rate and errors correlated from run
// to run (white scatter plus a slow AR(1) part, as the season's leftovers are): the intervals
// that allow the correlation (block_jackknife.h) hold the truth about as often as their level
// says, at 95 % and at 80 %, where the run-to-run scatter's own intervals fall well short.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "block_jackknife.h"
#include "daily_distance.h"
#include "wear_line_fit.h"

namespace flange::host {
namespace {

constexpr double kRatePerKm = 0.06 / 1000.0;

// 120 days (three stretches of 40 days), a depot day with chance 0.15, 150-750 km on the others; a
// reprofiling on day 70 when `reprofiled`. Errors: white (sd 0.004 mm) plus AR(1) with coefficient
// `phi` per day whose stationary sd is 0.01 mm.
WearSeries synthetic_series(std::mt19937& random, double phi, bool reprofiled) {
  std::uniform_real_distribution<double> unit(0.0, 1.0), km_of_day(150.0, 750.0);
  std::normal_distribution<double> white(0.0, 0.004), stationary(0.0, 0.01);
  std::normal_distribution<double> shock(0.0, 0.01 * std::sqrt(1.0 - phi * phi));
  WearSeries series;
  double odometer = 0.0, slow = stationary(random);
  double wear = 2.0;
  for (int day = 0; day < 120; ++day) {
    slow = phi * slow + shock(random);
    if (reprofiled && day == 70) wear = 0.5;
    const bool depot = unit(random) < 0.15;
    const double km = km_of_day(random);
    if (depot) continue;
    series.km.push_back(odometer);
    series.day.push_back(20454.0 + day + 0.25);
    series.y.push_back(2.0 + wear + slow + white(random));
    series.segment.push_back(reprofiled && day >= 70 ? 1 : 0);
    odometer += km;
    wear += kRatePerKm * km;
  }
  return series;
}

struct Held {
  double serial = 0.0, scatter_only = 0.0;
};

// How often the rate's interval at `level` holds the truth over `replicates` series.
Held coverage(double phi, bool reprofiled, double level, int replicates, std::uint32_t seed) {
  std::mt19937 random(seed);
  int serial = 0, scatter_only = 0;
  for (int k = 0; k < replicates; ++k) {
    const WearSeries series = synthetic_series(random, phi, reprofiled);
    const WearLineFit fit = fit_wear_line(series, std::nullopt);
    const SerialSpread spread = jackknife_rate(series, std::nullopt, 1, fit);
    const double error = std::abs(fit.rate_mm_per_km - kRatePerKm);
    serial += error <= t_quantile(level, spread.dof) * spread.rate_se ? 1 : 0;
    scatter_only += error <= t_quantile(level, fit.dof) * fit.rate_se ? 1 : 0;
  }
  return {static_cast<double>(serial) / replicates, static_cast<double>(scatter_only) / replicates};
}

// Errors correlated over about three weeks (AR(1) at 0.95 per day): the stretches left out
// hold them. Bounds: 1000 series give a binomial standard error under 1.3 %; the jackknife's
// few stretches make it somewhat conservative on fast errors and after a reprofiling (a
// stretch left out takes part of a flange's runs with it), somewhat liberal on slower ones.
TEST(WearInterval, HoldsAtItsLevelWhenErrorsAreCorrelatedFromDayToDay) {
  for (const bool reprofiled : {false, true}) {
    const Held at95 = coverage(0.95, reprofiled, 0.95, 1000, 11);
    EXPECT_GT(at95.serial, 0.91) << "reprofiled " << reprofiled;
    EXPECT_LT(at95.serial, 0.99) << "reprofiled " << reprofiled;
    EXPECT_LT(at95.scatter_only, 0.85) << "reprofiled " << reprofiled;
    const Held at80 = coverage(0.95, reprofiled, 0.80, 1000, 12);
    EXPECT_GT(at80.serial, 0.74) << "reprofiled " << reprofiled;
    EXPECT_LT(at80.serial, 0.91) << "reprofiled " << reprofiled;
  }
}

TEST(WearInterval, HoldsAtItsLevelWhenErrorsAreIndependent) {
  const Held at95 = coverage(0.0, false, 0.95, 1000, 13);
  EXPECT_GT(at95.serial, 0.93);
  EXPECT_LT(at95.serial, 0.985);
  EXPECT_GT(at95.scatter_only, 0.93);
  const Held at80 = coverage(0.0, false, 0.80, 1000, 14);
  EXPECT_GT(at80.serial, 0.77);
  EXPECT_LT(at80.serial, 0.90);
}

TEST(DailyDistance, MeanSpreadAndItsErrorFromTheRuns) {
  // Runs on days 0, 1, 3, 4 (day 2 in the depot): days 0 to 3 ran 100, 300, 0 and 0 km.
  std::vector<WearObservation> runs{{1, "", 0.0, 0.0, 2.0},
                                    {2, "", 1.0, 100.0, 2.0},
                                    {3, "", 3.0, 400.0, 2.0},
                                    {4, "", 4.0, 400.0, 2.0}};
  const DailyDistance d = daily_distance(runs);
  EXPECT_DOUBLE_EQ(d.km_per_day, 100.0);  // 400 km over 4 days
  // Days 100, 300, 0, 0 about 100: (0 + 40000 + 10000 + 10000) / 3.
  EXPECT_NEAR(d.day_sd, std::sqrt(20000.0), 1e-9);
  EXPECT_NEAR(d.se, std::sqrt(20000.0) / 2.0, 1e-9);
}

}  // namespace
}  // namespace flange::host
