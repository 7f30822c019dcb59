// SPDX-License-Identifier: MIT
// The drift rules on their own (sensor_drift.h): the bar a drift must reach is set by what the
// locomotive's other axles show, and a drift that moved only one of the axle's two
// combinations is no sensor's.
#include "sensor_drift.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

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

// A deterministic scatter in [-1, 1] (a 32-bit linear congruential generator): the same runs on
// every platform.
std::vector<double> scatter(std::size_t n, std::uint32_t state) {
  std::vector<double> values;
  for (std::size_t k = 0; k < n; ++k) {
    state = state * 1664525u + 1013904223u;
    values.push_back(static_cast<double>(state >> 8) / static_cast<double>(1u << 23) - 1.0);
  }
  return values;
}

// One axle, 60 daily runs of 300 km: the right sensor drifts from day 30 by 0.03 mm a day (0.9
// mm by the last run), which moves the difference and the sum by as much; the difference
// scatters by 0.01 mm, the sum by `sum_scatter_mm`.
DriftCandidates right_sensor_drift(double sum_scatter_mm) {
  const std::size_t n = 60;
  const std::vector<double> noise_difference = scatter(n, 7), noise_sum = scatter(n, 11);
  WearSeries difference, left, right;
  std::vector<double> sum(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double day = 20000.0 + static_cast<double>(k), km = 300.0 * static_cast<double>(k);
    const double drift = k >= 30 ? 0.03 * static_cast<double>(k - 30) : 0.0;
    for (WearSeries* series : {&difference, &left, &right}) {
      series->day.push_back(day);
      series->km.push_back(km);
      series->segment.push_back(0);
    }
    difference.y.push_back(0.00002 * km + drift + 0.01 * noise_difference[k]);
    sum[k] = 2.0 + 0.0001 * km + drift + sum_scatter_mm * noise_sum[k];
    left.y.push_back((sum[k] - difference.y[k]) / 2.0);
    right.y.push_back((sum[k] + difference.y[k]) / 2.0);
  }
  return drift_candidates(difference, left, right);
}

TEST(SensorDrift, TheOtherCombinationMustHaveMovedSignificantly) {
  // A quiet sum moves with the difference's drift: a sensor's.
  const DriftCandidates quiet = right_sensor_drift(0.01);
  ASSERT_TRUE(quiet.in_difference.has_value());
  EXPECT_GE(std::abs(quiet.in_difference->difference_t), kDriftTStatistic);
  EXPECT_FALSE(quiet.in_difference->left);
  EXPECT_TRUE(quiet.in_difference->moved_other);
  // A sum scattering by 0.5 mm takes a drift term of half the size or more at that onset (0.6 mm
  // of 0.87 here) but at a t under kDriftTStatistic (2.4): nothing says the sum moved with it.
  const DriftCandidates noisy = right_sensor_drift(0.5);
  ASSERT_TRUE(noisy.in_difference.has_value());
  EXPECT_GE(std::abs(noisy.in_difference->difference_t), kDriftTStatistic);
  EXPECT_GE(noisy.in_difference->size_mm, kMinDriftMm);
  EXPECT_FALSE(noisy.in_difference->moved_other);
}

}  // namespace
}  // namespace flange::host
