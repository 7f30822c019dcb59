// SPDX-License-Identifier: MIT
// BlockResamples: the held-out part's block bootstrap, kept as blocks, scored from running sums.
#include "block_resamples.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace flange::diagnose {
namespace {

// The index sets of the block bootstrap drawn index by index, the reference that the blocks
// must reproduce: with the same index sets, every inclusion and bootstrap quantile is the same.
std::vector<std::vector<std::size_t>> index_sets(std::size_t n, int rounds, std::uint64_t seed) {
  const std::size_t block = std::max<std::size_t>(32, n / 20);
  std::mt19937_64 random(seed);
  std::uniform_int_distribution<std::size_t> start(0, n > block ? n - block : 0);
  std::vector<std::vector<std::size_t>> sets(static_cast<std::size_t>(rounds));
  for (auto& set : sets) {
    while (set.size() < n) {
      const std::size_t s = start(random);
      for (std::size_t i = s; i < std::min(n, s + block) && set.size() < n; ++i) set.push_back(i);
    }
  }
  return sets;
}

TEST(BlockResamples, DrawsTheIndexSetsOfTheSameSeed) {
  for (const std::size_t n :
       {std::size_t{5}, std::size_t{31}, std::size_t{640}, std::size_t{9001}}) {
    const BlockResamples resamples(n, 7, 42);
    const auto expected = index_sets(n, 7, 42);
    ASSERT_EQ(resamples.size(), 7u);
    for (std::size_t r = 0; r < resamples.size(); ++r) {
      EXPECT_EQ(resamples.indices(r), expected[r]) << "n " << n << ", resample " << r;
    }
  }
}

TEST(BlockResamples, MeanSquaresAreThoseOfTheDrawnValues) {
  const std::size_t n = 270000;  // a 45-minute held-out part at 100 Hz
  std::mt19937_64 rng(5);
  std::normal_distribution<double> noise(0.0, 0.07);
  std::vector<double> e(n);
  for (std::size_t i = 0; i < n; ++i) e[i] = 0.3 * std::sin(1e-4 * static_cast<double>(i)) + noise(rng);
  const BlockResamples resamples(n, 20, 11);
  const std::vector<double> fast = resamples.mean_squares(e);
  ASSERT_EQ(fast.size(), 20u);
  for (std::size_t r = 0; r < resamples.size(); ++r) {
    double sum = 0.0;
    for (const std::size_t i : resamples.indices(r)) sum += e[i] * e[i];
    EXPECT_NEAR(fast[r], sum / static_cast<double>(n), 1e-12 * fast[r]) << "resample " << r;
  }
  // Equal gaps give equal scores, so a pick the final fit does not need counts as not needed.
  EXPECT_EQ(resamples.mean_squares(e), fast);
}

TEST(BlockResamples, NoRoundsAndNoValuesGiveNothing) {
  EXPECT_TRUE(BlockResamples(100, 0, 1).empty());
  const BlockResamples empty(0, 3, 1);
  EXPECT_EQ(empty.mean_squares({}), std::vector<double>(3, 0.0));
}

}  // namespace
}  // namespace flange::diagnose
