// SPDX-License-Identifier: MIT
// The whole locomotive: one wheel is the single-wheel run; left and right wheels of an axle see
// opposite clearance changes; a trailing axle meets the track later by its distance at the
// train's speed; the temperature is shared; each wheel has its own flange and seed.
#include "locomotive.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <vector>

#include "loco_scenario.h"
#include "locomotive_wheels.h"

namespace flange::sim {
namespace {

TEST(LocomotiveWheels, ChannelsRunAxleByAxleLeftThenRight) {
  EXPECT_EQ(wheel_position(0).axle, 1);
  EXPECT_EQ(wheel_position(0).side, WheelSide::kLeft);
  EXPECT_EQ(wheel_position(1).axle, 1);
  EXPECT_EQ(wheel_position(1).side, WheelSide::kRight);
  EXPECT_EQ(wheel_position(10).axle, 6);
  EXPECT_EQ(wheel_position(11).side, WheelSide::kRight);
  EXPECT_THROW(wheel_position(12), std::out_of_range);
  EXPECT_THROW(wheel_position(-1), std::out_of_range);
}

TEST(LocomotiveWheels, AxlesSitAlongTwoBogies) {
  const AxleLayout layout;
  const std::vector<double> expected = {0.0, 2.0, 4.0, 11.0, 13.0, 15.0};
  for (int axle = 1; axle <= kLocomotiveAxles; ++axle) {
    EXPECT_DOUBLE_EQ(axle_offset_m(layout, axle), expected[static_cast<std::size_t>(axle - 1)]);
  }
}

TEST(LocomotiveWheels, FlangesSpreadAsDocumentedAroundTheNominalOne) {
  const FlangeWear nominal{4.0, 4.5};
  const WheelSpread spread;
  const FlangeWear first = flange_wear(nominal, spread, 0);
  EXPECT_EQ(first.initial_clearance_mm, 4.0);
  EXPECT_EQ(first.wear_over_run_mm, 4.5);
  std::set<double> initial_values;
  for (int c = 1; c < kMaxWheels; ++c) {
    const FlangeWear wear = flange_wear(nominal, spread, c);
    EXPECT_GE(wear.initial_clearance_mm, 4.0) << c;
    EXPECT_LT(wear.initial_clearance_mm, 4.5) << c;
    if (wheel_position(c).side == WheelSide::kLeft) {
      EXPECT_GT(wear.wear_over_run_mm, 2.7) << c;
      EXPECT_LE(wear.wear_over_run_mm, 4.5) << c;
    } else {
      EXPECT_GT(wear.wear_over_run_mm, 1.35) << c;
      EXPECT_LE(wear.wear_over_run_mm, 2.25) << c;
    }
    initial_values.insert(wear.initial_clearance_mm);
    // Fixed by the channel: the same locomotive every time.
    EXPECT_EQ(flange_wear(nominal, spread, c).wear_over_run_mm, wear.wear_over_run_mm) << c;
  }
  EXPECT_EQ(initial_values.size(), 11u);  // every wheel its own
}

TEST(LocomotiveWheels, SeedsDifferPerChannelAndAreReproducible) {
  for (const std::uint64_t seed : {0ULL, 1ULL, 42ULL, 18446744073709551615ULL}) {
    EXPECT_EQ(wheel_seed(seed, 0), seed);  // channel 0 is the single-wheel run
    std::set<std::uint64_t> seeds;
    for (int c = 0; c < kMaxWheels; ++c) {
      seeds.insert(wheel_seed(seed, c));
      EXPECT_EQ(wheel_seed(seed, c), wheel_seed(seed, c));
    }
    EXPECT_EQ(seeds.size(), static_cast<std::size_t>(kMaxWheels)) << seed;
  }
  EXPECT_NE(wheel_seed(1, 5), wheel_seed(2, 5));
}

TEST(Locomotive, OneWheelIsTheSingleWheelRunAndChannelZeroOfTwelve) {
  const LocoRun run;
  LocoScenario single(run, 50.0, 25.0);
  Locomotive twelve(run, 12, 50.0, 25.0);
  ASSERT_EQ(single.sample_count(), twelve.sample_count());
  for (std::int64_t n = 0; n < single.sample_count(); ++n) {
    const TrueState one = single.next();
    const TrueState first = twelve.next().front();
    ASSERT_EQ(one.t_s, first.t_s) << n;
    ASSERT_EQ(one.clearance_mm, first.clearance_mm) << n;
    ASSERT_EQ(one.temperature_c, first.temperature_c) << n;
  }
}

TEST(Locomotive, LeftAndRightWheelsOfAnAxleSeeOppositeChangesInTheCurve) {
  const LocoRun run;
  const double duration_s = 63.0;                    // three laps of 21 s
  Locomotive locomotive(run, 12, 20.0, duration_s);  // 0.05 s: every axle's delay
  const double shift_mm = run.wheelset.supported_mass_kg * unbalanced_acceleration_mps2(run.track) /
                          (run.wheelset.leads * run.wheelset.lead_stiffness_n_per_m) * 1e3;
  int mid_curve_samples = 0;
  for (std::int64_t n = 0; n < locomotive.sample_count(); ++n) {
    const std::vector<TrueState>& truth = locomotive.next();
    for (int axle = 1; axle <= kLocomotiveAxles; ++axle) {
      const int left = 2 * (axle - 1);
      const int right = left + 1;
      const auto static_mm = [&](int c) {
        return locomotive.flange(c).initial_clearance_mm +
               locomotive.flange(c).wear_over_run_mm * truth[0].t_s / duration_s;
      };
      const double left_change = truth[left].clearance_mm - static_mm(left);
      const double right_change = truth[right].clearance_mm - static_mm(right);
      ASSERT_NEAR(left_change, -right_change, 1e-9) << "axle " << axle << ", t " << truth[0].t_s;
      ASSERT_NEAR(left_change, -locomotive.lateral_displacement_mm(axle), 1e-9);
      // Mid-curve for this axle, 200 m into its lap: the left gap closes, the right one opens.
      const double lap_s = std::fmod(truth[0].t_s - axle_offset_m(run.axles, axle) / 20.0, 21.0);
      if (std::abs(lap_s - 10.5) < 1e-6) {
        EXPECT_NEAR(left_change, -shift_mm, 0.02) << "axle " << axle << ", t " << truth[0].t_s;
        EXPECT_NEAR(right_change, shift_mm, 0.02) << "axle " << axle << ", t " << truth[0].t_s;
        ++mid_curve_samples;
      }
    }
  }
  EXPECT_EQ(mid_curve_samples, 6 * 3);  // every axle on each of the three laps
}

TEST(Locomotive, ATrailingAxleMeetsTheTrackLaterByItsDistanceAtTheTrainsSpeed) {
  // At 100 Hz axle 4, 11 m behind at 20 m/s, is 55 samples behind the leading axle; its start
  // from rest elsewhere on the lap has died out (damping ratio 0.071 at 6.4 Hz) after 10 s.
  const LocoRun run;
  Locomotive locomotive(run, 8, 100.0, 40.0);
  std::vector<double> leading, fourth;
  for (std::int64_t n = 0; n < locomotive.sample_count(); ++n) {
    locomotive.next();
    leading.push_back(locomotive.lateral_displacement_mm(1));
    fourth.push_back(locomotive.lateral_displacement_mm(4));
  }
  double largest_mm = 0.0;
  double largest_gap_mm = 0.0;
  for (std::size_t n = 1000; n < fourth.size(); ++n) {
    largest_mm = std::max(largest_mm, std::abs(fourth[n]));
    largest_gap_mm = std::max(largest_gap_mm, std::abs(fourth[n] - leading[n - 55]));
  }
  EXPECT_GT(largest_mm, 2.0);       // the curve's shift is there ...
  EXPECT_LT(largest_gap_mm, 1e-6);  // ... 0.55 s after the leading axle's
  // Without the delay the two differ by far more (the curve entry's ramp, the ringing).
  double undelayed_gap_mm = 0.0;
  for (std::size_t n = 1000; n < fourth.size(); ++n) {
    undelayed_gap_mm = std::max(undelayed_gap_mm, std::abs(fourth[n] - leading[n]));
  }
  EXPECT_GT(undelayed_gap_mm, 0.5);
}

TEST(Locomotive, EveryWheelSharesTheTemperature) {
  Locomotive locomotive(LocoRun{}, 12, 5.0, 300.0);
  for (std::int64_t n = 0; n < locomotive.sample_count(); ++n) {
    const std::vector<TrueState>& truth = locomotive.next();
    for (const TrueState& wheel : truth) ASSERT_EQ(wheel.temperature_c, truth[0].temperature_c);
  }
}

TEST(Locomotive, RefusesAWheelCountOutsideOneToTwelve) {
  EXPECT_THROW(Locomotive(LocoRun{}, 0, 10.0, 1.0), std::out_of_range);
  EXPECT_THROW(Locomotive(LocoRun{}, 13, 10.0, 1.0), std::out_of_range);
}

}  // namespace
}  // namespace flange::sim
