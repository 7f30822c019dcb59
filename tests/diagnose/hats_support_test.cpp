// SPDX-License-Identifier: MIT
// Hats::support (free_shapes/hats.h): a column is weighed only on the knots around each value,
// so every knot outside the support must weigh exactly +0.0 there, within the range, on the
// knots, beyond both ends with and without a reach, and for a range of one value.
#include <gtest/gtest.h>

#include <cmath>

#include "hats.h"

namespace flange::diagnose::free_shapes {
namespace {

void expect_zero_off_support(const Hats& hats, double x) {
  const auto [first, last] = hats.support(x);
  ASSERT_LE(first, last);
  ASSERT_LT(last, hats.knots.size());
  for (std::size_t k = 0; k < hats.knots.size(); ++k) {
    if (k >= first && k <= last) continue;
    const double w = hats.weight(k, x);
    EXPECT_EQ(w, 0.0) << "knot " << k << " at x = " << x;
    EXPECT_FALSE(std::signbit(w)) << "knot " << k << " at x = " << x;
  }
}

TEST(HatsSupport, EveryWeightOffTheSupportIsPositiveZero) {
  for (const double reach : {0.0, 1.0, 3.0}) {
    Hats hats = hats_between(20.0, 80.0, 7);
    hats.reach_both(reach);
    for (double x = -40.0; x <= 140.0; x += 0.37) expect_zero_off_support(hats, x);
    for (const double knot : hats.knots) expect_zero_off_support(hats, knot);
  }
  const Hats many = hats_between(1.0, 9.0, 25);
  for (double x = 0.0; x <= 10.0; x += 0.013) expect_zero_off_support(many, x);
}

TEST(HatsSupport, ARangeOfOneValueWeighsEveryKnot) {
  const Hats flat = hats_between(5.0, 5.0, 7);
  const auto [first, last] = flat.support(5.0);
  EXPECT_EQ(first, 0u);
  EXPECT_EQ(last, 6u);
}

}  // namespace
}  // namespace flange::diagnose::free_shapes
