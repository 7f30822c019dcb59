// SPDX-License-Identifier: MIT
#include "fidelity.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fmt/format.h>
#include <limits>
#include <stdexcept>

namespace flange::model {

double snr_db(const std::vector<double>& reference, const std::vector<double>& test) {
  if (reference.size() != test.size()) throw std::invalid_argument("snr_db: length mismatch");
  double signal = 0.0;
  double noise = 0.0;
  for (std::size_t i = 0; i < reference.size(); ++i) {
    signal += reference[i] * reference[i];
    noise += (test[i] - reference[i]) * (test[i] - reference[i]);
  }
  if (signal == 0.0) throw std::invalid_argument("snr_db: the reference is all zeros");
  if (noise == 0.0) return std::numeric_limits<double>::infinity();
  return 10.0 * std::log10(signal / noise);
}

double max_abs_error(const std::vector<double>& reference, const std::vector<double>& test) {
  if (reference.size() != test.size()) {
    throw std::invalid_argument("max_abs_error: length mismatch");
  }
  double worst = 0.0;
  for (std::size_t i = 0; i < reference.size(); ++i) {
    worst = std::max(worst, std::abs(test[i] - reference[i]));
  }
  return worst;
}

LimitCycle find_limit_cycle(const std::vector<std::int32_t>& y, std::size_t tail,
                            std::size_t max_period) {
  if (tail > y.size() || tail < 2 * max_period || max_period == 0) {
    throw std::invalid_argument("find_limit_cycle: need 1 <= 2 * max_period <= tail <= size");
  }
  const std::size_t start = y.size() - tail;
  LimitCycle lc;
  lc.minimum = *std::min_element(y.begin() + static_cast<std::ptrdiff_t>(start), y.end());
  lc.maximum = *std::max_element(y.begin() + static_cast<std::ptrdiff_t>(start), y.end());
  lc.amplitude = std::max(std::abs(lc.minimum), std::abs(lc.maximum));
  lc.decays_to_zero = lc.minimum == 0 && lc.maximum == 0;
  for (std::size_t p = 1; p <= max_period; ++p) {
    bool periodic = true;
    for (std::size_t n = start + p; n < y.size() && periodic; ++n) periodic = y[n] == y[n - p];
    if (periodic) {
      lc.period = p;
      break;
    }
  }
  // Walk back from the tail while the sequence keeps that period.
  std::size_t first = start;
  if (lc.period > 0) {
    while (first > 0 && y[first - 1] == y[first - 1 + lc.period]) --first;
  }
  lc.settled_after = first;
  return lc;
}

std::string LimitCycle::describe() const {
  if (decays_to_zero) return fmt::format("decays to 0 (zero from sample {})", settled_after);
  if (period == 1) {
    return fmt::format("dead band: stuck at {} LSB from sample {}", maximum, settled_after);
  }
  if (period > 1) {
    return fmt::format("limit cycle: amplitude {} LSB (range [{}, {}]), period {} samples, from "
                       "sample {}",
                       amplitude, minimum, maximum, period, settled_after);
  }
  return fmt::format("no period up to the search limit; amplitude {} LSB (range [{}, {}])",
                     amplitude, minimum, maximum);
}

}  // namespace flange::model
