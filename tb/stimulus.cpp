// SPDX-License-Identifier: MIT
#include "stimulus.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

namespace flange::tb {

std::int32_t full_scale_max(int sample_width) {
  return static_cast<std::int32_t>((std::int64_t{1} << (sample_width - 1)) - 1);
}
std::int32_t full_scale_min(int sample_width) {
  return static_cast<std::int32_t>(-(std::int64_t{1} << (sample_width - 1)));
}

namespace {
std::int32_t quantise(const SignalSpec& spec, double v) {
  const double scale = std::ldexp(1.0, spec.sample_width - 1);
  const double r = std::round(v * scale);
  return static_cast<std::int32_t>(
      std::clamp<double>(r, full_scale_min(spec.sample_width), full_scale_max(spec.sample_width)));
}
}  // namespace

std::vector<std::int32_t> impulse(const SignalSpec& spec, std::size_t n) {
  std::vector<std::int32_t> x(n, 0);
  if (n > 0) x[0] = full_scale_max(spec.sample_width);
  return x;
}

std::vector<std::int32_t> step(const SignalSpec& spec, std::size_t n, double level) {
  return std::vector<std::int32_t>(n, quantise(spec, level));
}

std::vector<std::int32_t> square(const SignalSpec& spec, std::size_t n, std::size_t half_period) {
  if (half_period == 0) throw std::invalid_argument("square: half_period must be >= 1");
  std::vector<std::int32_t> x(n);
  for (std::size_t i = 0; i < n; ++i) {
    x[i] = (i / half_period) % 2 == 0 ? full_scale_max(spec.sample_width)
                                      : full_scale_min(spec.sample_width);
  }
  return x;
}

double exponential_chirp_phase(double f0, double f1, double duration, double t) {
  const double k = std::log(f1 / f0);
  return 2.0 * std::numbers::pi * f0 * duration / k * (std::exp(k * t / duration) - 1.0);
}

std::vector<std::int32_t> sine_sweep(const SignalSpec& spec, std::size_t n, double f0, double f1,
                                     double level) {
  if (!(f0 > 0.0 && f0 < f1 && f1 <= spec.fs_hz / 2)) {
    throw std::invalid_argument("sine_sweep: need 0 < f0 < f1 <= fs / 2");
  }
  std::vector<std::int32_t> x(n);
  const double duration = static_cast<double>(n) / spec.fs_hz;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) / spec.fs_hz;
    x[i] = quantise(spec, level * std::sin(exponential_chirp_phase(f0, f1, duration, t)));
  }
  return x;
}

std::vector<std::int32_t> uniform_random(const SignalSpec& spec, std::size_t n, double level,
                                         std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const auto lo = static_cast<std::int32_t>(std::floor(level * full_scale_min(spec.sample_width)));
  const auto hi = static_cast<std::int32_t>(std::floor(level * full_scale_max(spec.sample_width)));
  std::uniform_int_distribution<std::int32_t> dist(lo, hi);
  std::vector<std::int32_t> x(n);
  for (auto& v : x) v = dist(rng);
  return x;
}

void Stimulus::add(const Action& action) {
  const auto pos =
      std::upper_bound(actions.begin(), actions.end(), action,
                       [](const Action& a, const Action& b) { return a.cycle < b.cycle; });
  actions.insert(pos, action);
}

std::uint64_t Stimulus::last_cycle() const { return actions.empty() ? 0 : actions.back().cycle; }

Stimulus every(const std::vector<std::int32_t>& samples, std::uint64_t spacing,
               std::uint64_t first_cycle) {
  Stimulus s;
  s.actions.reserve(samples.size());
  for (std::size_t i = 0; i < samples.size(); ++i) {
    s.actions.push_back({first_cycle + i * spacing, Action::Kind::kStrobe, samples[i]});
  }
  return s;
}

}  // namespace flange::tb
