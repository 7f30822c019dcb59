// SPDX-License-Identifier: MIT
// Small element-wise and order statistics on series that every stage uses.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>
#include <utility>
#include <vector>

namespace flange::diagnose {

// a - b, element by element (b at least as long as a).
inline std::vector<double> minus(const std::vector<double>& a, const std::vector<double>& b) {
  std::vector<double> d(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) d[i] = a[i] - b[i];
  return d;
}

// The q-quantile of v by linear interpolation between order statistics; 0 for an empty v.
inline double quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const double pos = q * static_cast<double>(v.size() - 1);
  const std::size_t lo = static_cast<std::size_t>(pos);
  const std::size_t hi = std::min(lo + 1, v.size() - 1);
  return v[lo] + (pos - static_cast<double>(lo)) * (v[hi] - v[lo]);
}

// The rate of a clock `t` (at least two increasing times): one over its median step. A logger
// that drops rows leaves the median step as it was, while (rows - 1) / duration falls by the
// share dropped: 1.5 % of rows dropped at 100 Hz move 60 Hz's alias by 1.5 Hz, ten times as far
// as the mains lines are looked for.
inline double rate_of_median_step(const std::vector<double>& t) {
  std::vector<double> steps(t.size() - 1);
  for (std::size_t i = 1; i < t.size(); ++i) steps[i - 1] = t[i] - t[i - 1];
  return 1.0 / quantile(std::move(steps), 0.5);
}

// The upper median (v must not be empty).
inline double median_of(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

// The RMS of `values` at the indices `at`; 0 for none.
inline double rms_at(const std::vector<double>& values, std::span<const std::size_t> at) {
  double sum_sq = 0.0;
  for (std::size_t i : at) sum_sq += values[i] * values[i];
  return at.empty() ? 0.0 : std::sqrt(sum_sq / static_cast<double>(at.size()));
}

}  // namespace flange::diagnose
