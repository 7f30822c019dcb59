// SPDX-License-Identifier: MIT
// The kink of a drift's onset (onset_kink.h): a sensor's creep from a day on fits far better from
// its onset than a smooth bend from the first run does, a smooth bend from the start does not.
#include "onset_kink.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace flange::host {
namespace {

// 90 days, a run on each day but every 6th, 150-750 km a day, a wear line of 0.05 mm per 1000 km
// and 0.005 mm of noise, plus `extra(day)`.
template <typename Extra>
WearSeries series_with(Extra extra, std::uint32_t seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> km_of_day(150.0, 750.0);
  std::normal_distribution<double> noise(0.0, 0.005);
  WearSeries series;
  double odometer = 0.0;
  for (int day = 0; day < 90; ++day) {
    if (day % 6 != 5) {
      series.km.push_back(odometer);
      series.day.push_back(20454.0 + day);
      series.y.push_back(3.0 + 0.05 * odometer / 1000.0 + extra(day) + noise(random));
      series.segment.push_back(0);
    }
    odometer += km_of_day(random);
  }
  return series;
}

TEST(OnsetKink, ADriftFromItsOnsetHasAKink) {
  for (const std::uint32_t seed : {1u, 2u, 3u}) {
    const WearSeries drift =
        series_with([](int day) { return day > 40 ? 0.01 * (day - 40) : 0.0; }, seed);
    EXPECT_GE(onset_kink(drift, fit_wear_line(drift, 20454.0 + 40.0, 2)), kOnsetKinkRatio)
        << "seed " << seed;
  }
}

TEST(OnsetKink, ASmoothBendFromTheStartHasNone) {
  // A wander that bends from the first day (0.3 mm over the 90 days, growing with the square of
  // the days): the drift search's terms from day 30 fit it, those from the first run as well.
  for (const std::uint32_t seed : {1u, 2u, 3u}) {
    const WearSeries bend =
        series_with([](int day) { return 0.3 * (day / 90.0) * (day / 90.0); }, seed);
    EXPECT_LT(onset_kink(bend, fit_wear_line(bend, 20454.0 + 30.0, 2)), kOnsetKinkRatio)
        << "seed " << seed;
  }
  // Without an onset there is no kink.
  const WearSeries flat = series_with([](int) { return 0.0; }, 4);
  EXPECT_EQ(onset_kink(flat, fit_wear_line(flat, std::nullopt)), 0.0);
}

// A drift from day 3 leaves too few runs before its onset for a bend from the first run to be
// told from it: it is not judged on its kink (infinity passes any bar).
TEST(OnsetKink, ADriftFromTheFirstDaysIsNotJudgedOnItsKink) {
  for (const std::uint32_t seed : {1u, 2u, 3u}) {
    const WearSeries early =
        series_with([](int day) { return day > 3 ? 0.01 * (day - 3) : 0.0; }, seed);
    EXPECT_TRUE(std::isinf(onset_kink(early, fit_wear_line(early, 20454.0 + 3.0, 2))))
        << "seed " << seed;
  }
}

}  // namespace
}  // namespace flange::host
