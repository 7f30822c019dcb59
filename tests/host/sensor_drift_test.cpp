// SPDX-License-Identifier: MIT
// The drift rules on their own (sensor_drift.h): the t a drift must reach is set by what the
// locomotive's other axles show, and a drift that moved only one of the axle's two
// combinations is no sensor's.
#include "sensor_drift.h"

#include <gtest/gtest.h>

namespace flange::host {
namespace {

DriftFinding finding(double t, double size_mm, bool moved_other = true) {
  DriftFinding f;
  f.difference_t = t;
  f.size_mm = size_mm;
  f.moved_other = moved_other;
  return f;
}

TEST(SensorDrift, TheTToReachIsSetByTheLocomotivesTypicalAxle) {
  // Six axles: the upper median of 4, 5, 5, 6, 7, 30 is 6, so a drift must reach 3 x 6.
  EXPECT_DOUBLE_EQ(drift_t_to_flag({30.0, 5.0, 7.0, 4.0, 6.0, 5.0}), kDriftTOverTypical * 6.0);
  // Quiet axles never lower the bound below kDriftTStatistic ...
  EXPECT_DOUBLE_EQ(drift_t_to_flag({0.0, 1.0, 0.5, 40.0}), kDriftTStatistic);
  // ... and with fewer than kMinAxlesForTypical axles there is nothing to compare with.
  EXPECT_DOUBLE_EQ(drift_t_to_flag({20.0, 30.0}), kDriftTStatistic);
}

TEST(SensorDrift, AFitTooSmallToMatterDoesNotCountTowardsTheTypical) {
  DriftCandidates small{finding(40.0, 0.5 * kMinDriftMm), finding(3.0, 1.0)};
  EXPECT_DOUBLE_EQ(drift_like_t(small), 3.0);
  EXPECT_DOUBLE_EQ(drift_like_t({}), 0.0);
}

TEST(SensorDrift, AFlaggedDriftMovedBothCombinationsAndIsLargeEnough) {
  const DriftCandidates clear{finding(20.0, 1.0), std::nullopt};
  ASSERT_TRUE(flagged_drift(clear, 18.0).has_value());
  EXPECT_FALSE(flagged_drift(clear, 21.0).has_value());  // below the locomotive's bound
  EXPECT_FALSE(flagged_drift({finding(20.0, 1.0, false), std::nullopt}, 6.0).has_value());
  EXPECT_FALSE(flagged_drift({finding(20.0, 0.5 * kMinDriftMm), std::nullopt}, 6.0).has_value());
  // Of two, the larger t; a negative drift counts by its size.
  DriftCandidates both{finding(-12.0, 1.0), finding(15.0, 1.0)};
  both.in_sum->in_sum = true;
  const auto chosen = flagged_drift(both, 6.0);
  ASSERT_TRUE(chosen.has_value());
  EXPECT_TRUE(chosen->in_sum);
}

}  // namespace
}  // namespace flange::host
