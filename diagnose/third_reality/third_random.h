// SPDX-License-Identifier: MIT
// The third reality's random numbers: std::mt19937_64 (its sequence is fixed by the standard)
// with the transforms written here (the normal by Marsaglia's polar method), so a seed gives the
// same pairs with every standard library.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>

namespace flange::third_reality {

class ThirdRandom {
 public:
  explicit ThirdRandom(std::uint64_t seed) : engine_(seed ^ 0xD1B54A32D192ED03ULL) {}

  // Uniform in (0, 1), from the top 53 bits of one output.
  double unit() { return (static_cast<double>(engine_() >> 11) + 0.5) / 9007199254740992.0; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * unit(); }
  // Every decade of [lo, hi] (lo > 0) equally likely.
  double log_uniform(double lo, double hi) { return std::exp(uniform(std::log(lo), std::log(hi))); }
  double sign() { return unit() < 0.5 ? -1.0 : 1.0; }
  bool chance(double p) { return unit() < p; }
  // 0 .. n-1 (n >= 1).
  int below(int n) { return std::min(n - 1, static_cast<int>(unit() * n)); }
  // Standard normal.
  double normal() {
    if (spare_) {
      spare_ = false;
      return spare_value_;
    }
    double u, v, s;
    do {
      u = 2.0 * unit() - 1.0;
      v = 2.0 * unit() - 1.0;
      s = u * u + v * v;
    } while (s >= 1.0);
    const double factor = std::sqrt(-2.0 * std::log(s) / s);
    spare_ = true;
    spare_value_ = v * factor;
    return u * factor;
  }
  // A seed for a sub-stream, exact in a double parameter (below 2^32).
  double child_seed() { return static_cast<double>(engine_() & 0xFFFFFFFFULL); }

 private:
  std::mt19937_64 engine_;
  bool spare_ = false;
  double spare_value_ = 0.0;
};

}  // namespace flange::third_reality
