// SPDX-License-Identifier: MIT
// Seeded Gaussian numbers that are the same on every standard library: std::mt19937_64's
// sequence is fixed by the C++ standard, whereas std::normal_distribution's algorithm is left to
// the implementation (libstdc++ and libc++ differ), so the transform to a normal is done here.
#pragma once

#include <cstdint>
#include <random>

namespace flange::sim {

// Mixes a seed and a stream number into an independent 64-bit seed (SplitMix64 finaliser), so
// that each random consumer (noise, each effect) has its own stream and enabling one effect
// does not shift another's numbers.
std::uint64_t derive_seed(std::uint64_t seed, std::uint64_t stream);

class GaussianSource {
 public:
  explicit GaussianSource(std::uint64_t seed) : engine_(seed) {}

  // Uniform in (0, 1): the top 53 bits of one engine output, never exactly 0.
  double uniform();
  // Standard normal by the Box-Muller transform (pairs; the second value is cached).
  double standard_normal();

 private:
  std::mt19937_64 engine_;
  double cached_ = 0.0;
  bool has_cached_ = false;
};

}  // namespace flange::sim
