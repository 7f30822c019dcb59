// SPDX-License-Identifier: MIT
// The alternative reality's own random numbers: std::mt19937_64 (its sequence is fixed by the
// standard) with the transforms written here, so a seed gives the same pairs on every standard
// library. Nothing here is shared with the sensor twin's GaussianSource.
#pragma once

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

namespace flange::alt_reality {

class AltRandom {
 public:
  explicit AltRandom(std::uint64_t seed) : engine_(seed) {}

  // Uniform in (0, 1), from the top 53 bits of one output.
  double unit() { return (static_cast<double>(engine_() >> 11) + 0.5) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * unit(); }
  // Uniform in log: every decade of [lo, hi] (lo > 0) equally likely.
  double log_uniform(double lo, double hi) { return lo * std::pow(hi / lo, unit()); }
  double sign() { return unit() < 0.5 ? -1.0 : 1.0; }
  // 0 .. n-1.
  int index(int n) { return std::min(n - 1, static_cast<int>(unit() * n)); }
  // Standard normal (Box-Muller, one value per call).
  double normal() {
    return std::sqrt(-2.0 * std::log(unit())) * std::cos(2.0 * std::numbers::pi * unit());
  }
  // A 32-bit seed for a sub-stream (kept exactly in a double parameter).
  double sub_seed() { return static_cast<double>(engine_() >> 32); }

 private:
  std::mt19937_64 engine_;
};

}  // namespace flange::alt_reality
