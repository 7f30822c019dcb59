// SPDX-License-Identifier: MIT
// The per-run static clearance of an axle: the lateral shift cancels in left + right, the
// median of right - left is the centred wheelset's, the leftover temperature slope is removed.
#include "axle_clearance.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace flange::host {
namespace {

// A run of n samples: the first `curve_share` of them in a curve (shift 2.5 mm towards the
// left rail), the rest on tangent; the sensors read `slope` mm more per degC above 30 degC.
std::pair<WheelSamples, WheelSamples> run(double left_mm, double right_mm, double curve_share,
                                          double slope) {
  WheelSamples left, right;
  const int n = 1000;
  for (int k = 0; k < n; ++k) {
    const double shift = k < curve_share * n ? 2.5 : 0.0;
    const double temp = 30.0 + 60.0 * std::sin(0.01 * k) * std::sin(0.01 * k);
    const double leftover = slope * (temp - 30.0);
    left.clearance_mm.push_back(left_mm - shift + leftover);
    right.clearance_mm.push_back(right_mm + shift + leftover);
    left.temp_c.push_back(temp);
    right.temp_c.push_back(temp);
  }
  return {left, right};
}

TEST(AxleClearance, ShiftCancelsAndTemperatureLeftoverIsRemoved) {
  const auto [left, right] = run(4.2, 3.1, 0.3, 0.004);
  const std::optional<AxleClearance> axle = axle_clearance(left, right);
  ASSERT_TRUE(axle.has_value());
  EXPECT_NEAR(axle->left_mm, 4.2, 1e-9);
  EXPECT_NEAR(axle->right_mm, 3.1, 1e-9);
  EXPECT_NEAR(axle->temp_slope_mm_per_c, 0.008, 1e-9);  // the sum carries both sensors' slope
  EXPECT_EQ(axle->samples, 700u);                       // the tangent's samples only
}

TEST(AxleClearance, ASensorOnTheBottomRailInTheCurveDoesNotBiasIt) {
  auto [left, right] = run(2.2, 3.1, 0.3, 0.0);
  for (double& c : left.clearance_mm) c = std::max(c, 1.09);  // the range's bottom: 0 V
  const std::optional<AxleClearance> axle = axle_clearance(left, right);
  ASSERT_TRUE(axle.has_value());
  EXPECT_NEAR(axle->left_mm, 2.2, 1e-9);
  EXPECT_NEAR(axle->right_mm, 3.1, 1e-9);
}

TEST(AxleClearance, TheMedianOnlyHoldsWhileTheCurveIsUnderHalfTheRun) {
  const auto [left, right] = run(4.2, 3.1, 0.6, 0.0);
  const std::optional<AxleClearance> axle = axle_clearance(left, right);
  ASSERT_TRUE(axle.has_value());
  EXPECT_NEAR(axle->left_mm + axle->right_mm, 7.3, 1e-9);  // the sum still holds
  EXPECT_NEAR(axle->left_mm, 4.2 - 2.5, 1e-9);             // the difference is the curve's
  EXPECT_EQ(axle->samples, 600u);
}

// A day whose curves are mostly of one hand (30 % of the run shifted 0.4-1.2 mm to the right,
// 10 % 0.6 mm to the left) with the wheelset swinging 0.12 mm about its centre on tangent: the
// median of right - left over the run sits in the tangent's lower part, the mode in its middle.
TEST(AxleClearance, UnevenCurvesDoNotMoveTheCentre) {
  WheelSamples left, right;
  for (int k = 0; k < 1200; ++k) {
    const double place = static_cast<double>(k % 400) / 400.0;
    const double shift = place < 0.3   ? -(0.4 + 0.8 * place / 0.3)
                         : place < 0.4 ? 0.6
                                       : 0.12 * std::sin(2.0 * 3.14159265358979 * k / 7.3);
    left.clearance_mm.push_back(4.2 - shift);
    right.clearance_mm.push_back(3.1 + shift);
    left.temp_c.push_back(30.0);
    right.temp_c.push_back(30.0);
  }
  std::vector<double> differences;
  for (int k = 0; k < 1200; ++k) differences.push_back(right.clearance_mm[k] - left.clearance_mm[k]);
  std::nth_element(differences.begin(), differences.begin() + 600, differences.end());
  EXPECT_LT(differences[600] / 2.0, -1.1 / 2.0 - 0.04);  // the run's median: 0.04 mm off or more
  const std::optional<AxleClearance> axle = axle_clearance(left, right);
  ASSERT_TRUE(axle.has_value());
  EXPECT_NEAR(axle->left_mm, 4.2, 0.005);
  EXPECT_NEAR(axle->right_mm, 3.1, 0.005);
}

TEST(AxleClearance, NonFiniteSamplesAreLeftOutAndTooFewGiveNothing) {
  WheelSamples left{{NAN, 4.0}, {30.0, 30.0}};
  WheelSamples right{{3.0, NAN}, {30.0, 30.0}};
  EXPECT_FALSE(axle_clearance(left, right).has_value());
  EXPECT_FALSE(lone_wheel_clearance({{NAN}, {30.0}}).has_value());
  EXPECT_DOUBLE_EQ(*lone_wheel_clearance({{1.0, 5.0, 2.0}, {30.0, 30.0, 30.0}}), 2.0);
}

}  // namespace
}  // namespace flange::host
