// SPDX-License-Identifier: MIT
// The half-sample mode stays in the densest cluster where the median is pulled off by the rest.
#include "robust_location.h"

#include <gtest/gtest.h>

#include <cmath>

namespace flange::host {
namespace {

TEST(RobustLocation, HalfSampleModeFindsTheDensestStretch) {
  // 60 values packed at 1.0 +- 0.01 and 40 spread over 2-6: the median is pulled to the
  // spread side, the mode stays at the pack.
  std::vector<double> values;
  for (int k = 0; k < 60; ++k) values.push_back(1.0 + 0.01 * std::sin(k));
  for (int k = 0; k < 40; ++k) values.push_back(2.0 + 0.1 * k);
  EXPECT_NEAR(half_sample_mode(values), 1.0, 0.01);
  EXPECT_GT(median(values), 1.005);
}

TEST(RobustLocation, SmallSets) {
  EXPECT_DOUBLE_EQ(half_sample_mode({3.0}), 3.0);
  EXPECT_DOUBLE_EQ(half_sample_mode({1.0, 2.0}), 1.5);
  EXPECT_DOUBLE_EQ(half_sample_mode({1.0, 2.0, 2.1}), 2.05);
  EXPECT_DOUBLE_EQ(half_sample_mode({1.0, 2.0, 3.0}), 2.0);
  EXPECT_DOUBLE_EQ(median({1.0, 5.0, 2.0}), 2.0);
  EXPECT_DOUBLE_EQ(median({1.0, 5.0, 2.0, 4.0}), 3.0);
}

}  // namespace
}  // namespace flange::host
