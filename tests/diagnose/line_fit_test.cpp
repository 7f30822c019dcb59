// SPDX-License-Identifier: MIT
// line_fit (series_statistics.h), the least-squares line the vibration signature and the mains
// family's motion check both stand on.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "series_statistics.h"

namespace flange::diagnose {
namespace {

TEST(LineFit, RecoversALineAndItsSlopesSignificance) {
  std::mt19937_64 rng(3);
  std::normal_distribution<double> noise(0.0, 0.1);
  std::vector<double> x, y, flat;
  for (int i = 0; i < 400; ++i) {
    x.push_back(0.01 * i);
    y.push_back(2.0 + 0.5 * x.back() + noise(rng));
    flat.push_back(2.0 + noise(rng));
  }
  const LineFit fit = line_fit(x, y);
  ASSERT_TRUE(fit.fitted);
  EXPECT_NEAR(fit.intercept, 2.0, 0.03);
  EXPECT_NEAR(fit.slope, 0.5, 0.02);
  EXPECT_GT(fit.slope_t, 30.0);
  EXPECT_LT(std::abs(line_fit(x, flat).slope_t), 4.0);
}

TEST(LineFit, NeedsThreePointsAndAnXThatVaries) {
  EXPECT_FALSE(line_fit({1.0, 2.0}, {1.0, 2.0}).fitted);
  EXPECT_FALSE(line_fit({1.0, 1.0, 1.0}, {1.0, 2.0, 3.0}).fitted);
  EXPECT_FALSE(line_fit({1.0, 2.0, 3.0}, {1.0, 2.0}).fitted);
}

}  // namespace
}  // namespace flange::diagnose
