// SPDX-License-Identifier: MIT
#include "gaussian_source.h"

#include <cmath>
#include <numbers>

namespace flange::sim {

std::uint64_t derive_seed(std::uint64_t seed, std::uint64_t stream) {
  std::uint64_t z = seed + (stream + 1) * 0x9E3779B97F4A7C15ULL;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

double GaussianSource::uniform() {
  constexpr double kTwoToMinus53 = 1.0 / 9007199254740992.0;
  return (static_cast<double>(engine_() >> 11) + 0.5) * kTwoToMinus53;
}

double GaussianSource::standard_normal() {
  if (has_cached_) {
    has_cached_ = false;
    return cached_;
  }
  const double radius = std::sqrt(-2.0 * std::log(uniform()));
  const double angle = 2.0 * std::numbers::pi * uniform();
  cached_ = radius * std::sin(angle);
  has_cached_ = true;
  return radius * std::cos(angle);
}

}  // namespace flange::sim
