// SPDX-License-Identifier: MIT
// The blind self-test's random draws, from each case's own stream, so that case k is the same
// whatever the number of cases.
#pragma once

#include <cstdint>
#include <random>

namespace flange::diagnose {

class SelftestDraw {
 public:
  explicit SelftestDraw(std::uint64_t seed) : rng_(seed) {}
  // Uniform in [lo, hi).
  double uniform(double lo, double hi) {
    return lo + (hi - lo) * std::uniform_real_distribution<double>(0.0, 1.0)(rng_);
  }
  // A magnitude uniform in [lo, hi) with a random sign (the sign drawn first).
  double signed_magnitude(double lo, double hi) { return sign() * uniform(lo, hi); }
  double sign() { return index(2) == 0 ? -1.0 : 1.0; }
  // Uniform in 0 .. n - 1.
  int index(int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng_); }
  std::uint64_t seed() { return rng_(); }

 private:
  std::mt19937_64 rng_;
};

}  // namespace flange::diagnose
