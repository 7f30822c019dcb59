// SPDX-License-Identifier: MIT
// The second fleet reality's own random numbers: std::mt19937_64 (its sequence is fixed by the
// standard) with the transforms written here, and independent streams named by numbers, so a
// seed gives the same fleet on every standard library. Nothing is shared with sim/.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

namespace flange::fleet_alt {

class FleetRandom {
 public:
  explicit FleetRandom(std::uint64_t seed) : engine_(seed) {}
  // The stream `stream` of `seed`: a splitmix64 step of both, so nearby numbers give unrelated
  // sequences.
  FleetRandom(std::uint64_t seed, std::uint64_t stream) : engine_(mix(seed ^ mix(stream + 1))) {}

  // Uniform in (0, 1), from the top 53 bits of one output.
  double unit() { return (static_cast<double>(engine_() >> 11) + 0.5) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * unit(); }
  bool chance(double p) { return unit() < p; }
  double sign() { return unit() < 0.5 ? -1.0 : 1.0; }
  // 0 .. n-1.
  int index(int n) { return std::min(n - 1, static_cast<int>(unit() * n)); }
  // Standard normal (Box-Muller, one value per call).
  double normal() {
    return std::sqrt(-2.0 * std::log(unit())) * std::cos(2.0 * std::numbers::pi * unit());
  }

 private:
  static std::uint64_t mix(std::uint64_t z) {
    z += 0x9e3779b97f4a7c15ULL;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  std::mt19937_64 engine_;
};

}  // namespace flange::fleet_alt
