// SPDX-License-Identifier: MIT
// The fleet's prior on the jackknife's inflation (moderated_spread.h): it finds the typical
// inflation and how much the wheels' own differ beyond their chance, and moderates each wheel
// between its own and the prior by their degrees of freedom.
#include "moderated_spread.h"

#include <gtest/gtest.h>

#include <boost/math/special_functions/trigamma.hpp>
#include <cmath>
#include <limits>
#include <random>

namespace flange::host {
namespace {

// `wheels` inflations s0 c_w chi2_dof / dof, c_w = exp(N(0, spread)) (spread 0: no real
// difference between the wheels).
std::vector<SerialSpread> drawn(double s0, int dof, double spread, int wheels, std::uint32_t seed) {
  std::mt19937 random(seed);
  std::chi_squared_distribution<double> chance(dof);
  std::normal_distribution<double> between(0.0, spread);
  std::vector<SerialSpread> spreads;
  for (int w = 0; w < wheels; ++w) {
    const double inflation = s0 * std::exp(spread > 0.0 ? between(random) : 0.0) *
                             chance(random) / dof;
    spreads.push_back({std::sqrt(inflation), inflation, dof, dof + 1});
  }
  return spreads;
}

TEST(ModeratedSpread, InverseTrigammaInvertsTrigamma) {
  for (const double y : {0.01, 0.3, 1.0, 2.5, 40.0, 3000.0}) {
    EXPECT_NEAR(inverse_trigamma(boost::math::trigamma(y)), y, 1e-6 * y) << y;
  }
}

TEST(ModeratedSpread, WheelsThatDifferOnlyByChanceArePooled) {
  const InflationPrior prior = inflation_prior(drawn(3.0, 5, 0.0, 4000, 1));
  EXPECT_GT(prior.dof, 200.0);  // infinite or nearly: their scatter is their own dof's
  EXPECT_NEAR(prior.inflation, 3.0, 0.15);
}

TEST(ModeratedSpread, WheelsThatDifferKeepPartOfTheirOwn) {
  // Log-normal differences of sd 0.5 are near a scaled inverse chi-square with d0 about 8.
  const InflationPrior prior = inflation_prior(drawn(3.0, 5, 0.5, 4000, 2));
  EXPECT_GT(prior.dof, 5.0);
  EXPECT_LT(prior.dof, 14.0);
  EXPECT_NEAR(prior.inflation, 3.0, 0.5);
}

TEST(ModeratedSpread, EachWheelBetweenItsOwnAndThePriorByDegreesOfFreedom) {
  const SerialSpread own{2.0, 4.0, 5, 6};  // inflation 4 from a least-squares se of 1
  const SerialSpread moderated = moderated_spread(own, {10.0, 1.0}, 1.0);
  EXPECT_NEAR(moderated.inflation, (10.0 * 1.0 + 5.0 * 4.0) / 15.0, 1e-12);
  EXPECT_NEAR(moderated.rate_se, std::sqrt(2.0), 1e-12);
  EXPECT_EQ(moderated.dof, 15);
  const SerialSpread pooled =
      moderated_spread(own, {std::numeric_limits<double>::infinity(), 1.5}, 2.0);
  EXPECT_NEAR(pooled.rate_se, 2.0 * std::sqrt(1.5), 1e-12);
  EXPECT_EQ(pooled.dof, kMaxModeratedDof);
}

TEST(ModeratedSpread, NoPriorFromTooFewWheelsAndNoneForAWheelWithoutAJackknife) {
  EXPECT_EQ(inflation_prior(drawn(3.0, 5, 0.0, kMinPriorWheels - 1, 3)).dof, 0.0);
  const SerialSpread own{2.0, 4.0, 5, 6};
  EXPECT_EQ(moderated_spread(own, {}, 1.0).dof, 5);
  const SerialSpread least_squares{1.0, 1.0, 40, 0};
  EXPECT_EQ(moderated_spread(least_squares, {10.0, 2.0}, 1.0).dof, 40);
}

}  // namespace
}  // namespace flange::host
