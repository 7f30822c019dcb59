// SPDX-License-Identifier: MIT
// Wear that speeds up as the flange thins, pooled over a fleet (wear_acceleration.h): on synthetic
// fleets whose wear per km is r exp(b wear) the fleet's b is found and the km to the warning
// clearance hold their level; on fleets that wear linearly the b found, within 0, is the dates'.
#include "wear_acceleration.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "fleet_wear.h"
#include "host/synthetic_accelerating_fleet.h"
#include "limit_forecast.h"
#include "season_to_come.h"

namespace flange::host {
namespace {

using testing::SyntheticFleet;

SyntheticFleet synthetic_fleet(double b, std::uint32_t seed) {
  return testing::synthetic_accelerating_fleet(b, seed);
}

// The median of the true km (a wheel's position: its locomotive's number and channel) to the
// warning over the forecast's, over the fleet's wheels.
double median_true_over_forecast(const SyntheticFleet& truth, const FleetWear& fleet) {
  std::vector<double> ratios;
  for (const WheelWear& w : fleet.wheels) {
    if (!w.warning.km || w.warning.reached) continue;
    const int position = (std::stoi(w.wheel.locomotive.substr(1)) - 1) * 12 + w.wheel.channel;
    ratios.push_back(truth.true_km_to_warning[static_cast<std::size_t>(position)] / *w.warning.km);
  }
  std::nth_element(ratios.begin(), ratios.begin() + ratios.size() / 2, ratios.end());
  return ratios[ratios.size() / 2];
}

TEST(WearAcceleration, AFleetWearingFasterAsItThinsIsFoundAndItsDatesHoldTheirLevel) {
  for (const std::uint32_t seed : {1u, 2u, 3u}) {
    const SyntheticFleet truth = synthetic_fleet(0.06, seed);
    const FleetWear fleet = estimate_fleet_wear(truth.histories, {});
    EXPECT_TRUE(fleet.acceleration.significant) << "seed " << seed;
    EXPECT_NEAR(fleet.acceleration.estimate, 0.06, 3.0 * fleet.acceleration.se) << "seed " << seed;
    // The straight line's km run about 15 % long here; with b the median is within 3 %.
    EXPECT_NEAR(median_true_over_forecast(truth, fleet), 1.0, 0.03) << "seed " << seed;
  }
}

// A fleet that wears linearly: its b is within 0 and is in the dates all the same, weighed by
// how well it is known (acceleration_in_dates: b^3 / (b^2 + se^2)), with its own uncertainty in
// the interval; the dates hold their level.
TEST(WearAcceleration, ABWithinZeroIsInTheDatesWeighedByItsUncertainty) {
  for (const std::uint32_t seed : {1u, 2u, 3u}) {
    const SyntheticFleet truth = synthetic_fleet(0.0, seed);
    const FleetWear fleet = estimate_fleet_wear(truth.histories, {});
    const FleetAcceleration& bend = fleet.acceleration;
    EXPECT_FALSE(bend.significant) << "seed " << seed;
    ASSERT_GT(bend.dof, 0);
    EXPECT_NEAR(median_true_over_forecast(truth, fleet), 1.0, 0.03) << "seed " << seed;
    for (const WheelWear& w : fleet.wheels) {
      if (!w.warning.km || w.warning.reached || w.sensor_fault) continue;
      const ForecastInput& input = w.forecast_input;
      EXPECT_EQ(input.acceleration_per_mm, acceleration_in_dates(bend));
      EXPECT_NE(input.acceleration_per_mm, 0.0);
      EXPECT_EQ(input.acceleration_se, bend.se);
      EXPECT_EQ(input.trend_se, bend.trend_se);
      EXPECT_EQ(input.acceleration_trend_covariance, bend.covariance);
      // The season carried forward from the fleet's trend (season_to_come.h).
      EXPECT_EQ(input.season_trend_per_day, bend.trend);
      EXPECT_NEAR(input.season_departure_days, w.runs.back().day - km_weighted_mean_day(w.runs),
                  1e-9);
    }
  }
}

// The b in the dates: the least-mean-square-error multiple of the estimate, b^2 / (b^2 + se^2),
// at the estimate: a b known well kept, one within its se of 0 taken down, 0 nothing.
TEST(WearAcceleration, TheDatesBIsTheEstimateWeighedByHowWellItIsKnown) {
  FleetAcceleration fleet;
  fleet.estimate = 0.06;
  fleet.se = 0.0015;
  EXPECT_NEAR(acceleration_in_dates(fleet), 0.06 * 0.0036 / (0.0036 + 0.0015 * 0.0015), 1e-15);
  EXPECT_GT(acceleration_in_dates(fleet), 0.0599);
  fleet.estimate = -0.003;
  fleet.se = 0.012;
  EXPECT_NEAR(acceleration_in_dates(fleet), -0.003 * 0.003 * 0.003 / (0.000009 + 0.000144), 1e-15);
  EXPECT_GT(acceleration_in_dates(fleet), -0.0002);
  fleet.estimate = fleet.se = 0.0;
  EXPECT_EQ(acceleration_in_dates(fleet), 0.0);
}

TEST(LimitForecast, AnAcceleratingFlangesKmToTheLimitFollowTheThinningLaw) {
  ForecastInput input{5.0, 0.05e-3, 0.04e-3, 0.06e-3, 300.0, 20000.0};
  input.clearance_now_se_mm = 0.02;
  input.rate_se_mm_per_km = 0.002e-3;
  input.dof = 8;
  const LimitForecast straight = forecast_limit(input, 8.0);
  ASSERT_TRUE(straight.km.has_value());
  EXPECT_NEAR(*straight.km, 3.0 / 0.05e-3, 1e-6);
  // b -> 0: the straight line's km and interval.
  input.acceleration_per_mm = 1e-12;
  const LimitForecast barely = forecast_limit(input, 8.0);
  EXPECT_NEAR(*barely.km, *straight.km, 1e-6 * *straight.km);
  EXPECT_NEAR(*barely.km_high, *straight.km_high, 1e-6 * *straight.km_high);
  // b = 0.06 per mm: (1 - exp(-b G)) / (b r), G = 3 mm; b's own uncertainty widens the interval.
  input.acceleration_per_mm = 0.06;
  const LimitForecast faster = forecast_limit(input, 8.0);
  EXPECT_NEAR(*faster.km, -std::expm1(-0.18) / (0.06 * 0.05e-3), 1e-6 * *faster.km);
  EXPECT_LT(*faster.km, *straight.km);
  input.acceleration_se = 0.02;
  input.acceleration_dof = 4;
  const LimitForecast uncertain = forecast_limit(input, 8.0);
  EXPECT_NEAR(*uncertain.km, *faster.km, 1e-9 * *faster.km);
  EXPECT_LT(*uncertain.km_low, *faster.km_low);
  EXPECT_GT(*uncertain.km_high, *faster.km_high);
}

}  // namespace
}  // namespace flange::host
