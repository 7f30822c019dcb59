// SPDX-License-Identifier: MIT
// The drift rules on their own (sensor_drift.h): the bar a drift must reach is set by what the
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

// One candidate per axle (in the difference), with these t's and sizes.
std::vector<DriftCandidates> axles(const std::vector<std::pair<double, double>>& t_and_size) {
  std::vector<DriftCandidates> result;
  for (const auto& [t, size] : t_and_size) result.push_back({finding(t, size), std::nullopt});
  return result;
}

TEST(SensorDrift, TheBarIsSetByTheLocomotivesTypicalAxle) {
  // Six axles: the upper median of the t's 4, 5, 5, 6, 7, 30 is 6, of the sizes 0.3 ... 3 is 0.5.
  const LocomotiveBar bar = locomotive_bar(
      axles({{30.0, 3.0}, {-5.0, 0.3}, {7.0, 0.5}, {4.0, 0.4}, {6.0, 0.6}, {5.0, 0.3}}));
  EXPECT_DOUBLE_EQ(bar.t, kDriftTOverTypical * 6.0);
  EXPECT_DOUBLE_EQ(bar.size_mm, kDriftSizeOverTypical * 0.5);
  // Quiet axles never lower the bar below kDriftTStatistic and kMinDriftMm ...
  const LocomotiveBar quiet = locomotive_bar(axles({{0.5, 0.01}, {1.0, 0.02}, {40.0, 2.0}}));
  EXPECT_DOUBLE_EQ(quiet.t, kDriftTStatistic);
  EXPECT_DOUBLE_EQ(quiet.size_mm, kMinDriftMm);
  // ... and with fewer than kMinAxlesForTypical axles there is nothing to stand out from.
  const LocomotiveBar two = locomotive_bar(axles({{20.0, 2.0}, {30.0, 3.0}}));
  EXPECT_DOUBLE_EQ(two.t, kDriftTStatistic);
  EXPECT_DOUBLE_EQ(two.size_mm, kMinDriftMm);
}

TEST(SensorDrift, AFitTooSmallToMatterSetsNoTypicalT) {
  // The t of 40 comes from a fit under kMinDriftMm: the typical t is that of the others (3).
  const LocomotiveBar bar =
      locomotive_bar(axles({{40.0, 0.5 * kMinDriftMm}, {40.0, 0.5 * kMinDriftMm}, {3.0, 1.0}}));
  EXPECT_DOUBLE_EQ(bar.t, kDriftTStatistic);
}

TEST(SensorDrift, AFlaggedDriftStandsOutByItsTOrByItsSize) {
  const LocomotiveBar bar{18.0, 1.0};
  EXPECT_TRUE(flagged_drift({finding(20.0, 0.5), std::nullopt}, bar).has_value());  // by t
  EXPECT_TRUE(flagged_drift({finding(8.0, 1.5), std::nullopt}, bar).has_value());   // by size
  EXPECT_FALSE(flagged_drift({finding(8.0, 0.5), std::nullopt}, bar).has_value());  // neither
  // Never below kDriftTStatistic or kMinDriftMm, and only when the other combination moved.
  EXPECT_FALSE(flagged_drift({finding(5.0, 3.0), std::nullopt}, bar).has_value());
  EXPECT_FALSE(flagged_drift({finding(30.0, 0.5 * kMinDriftMm), std::nullopt}, LocomotiveBar{})
                   .has_value());
  EXPECT_FALSE(flagged_drift({finding(20.0, 1.0, false), std::nullopt}, bar).has_value());
  // Of two, the larger t; a negative drift counts by its size.
  DriftCandidates both{finding(-19.0, 1.0), finding(25.0, 1.0)};
  both.in_sum->in_sum = true;
  const auto chosen = flagged_drift(both, bar);
  ASSERT_TRUE(chosen.has_value());
  EXPECT_TRUE(chosen->in_sum);
}

}  // namespace
}  // namespace flange::host
