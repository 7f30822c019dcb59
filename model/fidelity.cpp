// SPDX-License-Identifier: MIT
#include "fidelity.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
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
    return fmt::format(
        "limit cycle: amplitude {} LSB (range [{}, {}]), period {} samples, from "
        "sample {}",
        amplitude, minimum, maximum, period, settled_after);
  }
  return fmt::format("no period up to the search limit; amplitude {} LSB (range [{}, {}])",
                     amplitude, minimum, maximum);
}

namespace {

// sum |h[n]| of b(z) / a(z), a[0] = 1, until the response has decayed.
double l1_norm(const std::vector<double>& b, const std::vector<double>& a) {
  const std::size_t order = std::max(b.size(), a.size());
  std::vector<double> x(order, 0.0), y(order, 0.0);  // newest first
  double sum = 0.0;
  double recent = 0.0;  // sum |h| over the last 1000 samples
  for (std::size_t n = 0; n < 10'000'000; ++n) {
    std::rotate(x.rbegin(), x.rbegin() + 1, x.rend());
    std::rotate(y.rbegin(), y.rbegin() + 1, y.rend());
    x[0] = n == 0 ? 1.0 : 0.0;
    double h = 0.0;
    for (std::size_t i = 0; i < b.size(); ++i) h += b[i] * x[i];
    for (std::size_t j = 1; j < a.size(); ++j) h -= a[j] * y[j];
    y[0] = h;
    sum += std::abs(h);
    recent += std::abs(h);
    if (n % 1000 == 999) {
      if (n > 10 * order && recent < 1e-13 * sum) return sum;
      recent = 0.0;
    }
  }
  throw std::invalid_argument("limit_cycle_bound_lsb: a section's impulse response does not decay");
}

}  // namespace

double limit_cycle_bound_lsb(const CoreConfig& config) {
  std::vector<double> shaped_norm, inverse_norm, section_norm;
  for (int k = 0; k < config.num_sections; ++k) {
    const std::vector<double> a = config.a_values(k);
    // The fed-back rounding error passes 1 - sum_j E[j] z^-j before 1/A.
    std::vector<double> shaping{1.0};
    for (std::int64_t e : config.error_feedback(k)) shaping.push_back(-static_cast<double>(e));
    shaped_norm.push_back(l1_norm(shaping, a));
    inverse_norm.push_back(l1_norm({1.0}, a));
    section_norm.push_back(l1_norm(config.b_values(k), a));
  }
  double bound = 0.5;  // sample_o's own rounding
  for (int k = 0; k < config.num_sections; ++k) {
    const auto i = static_cast<std::size_t>(k);
    // In output LSB: half a y_ext LSB (2^-(s+1)) shaped by the error feedback, and below one
    // accumulator LSB (2^-(s+F)) from the lo phase's shift, which is not fed back.
    double gain = std::ldexp(0.5, -config.feedback_shift) * shaped_norm[i] +
                  std::ldexp(1.0, -(config.feedback_shift + config.coef_frac_bits)) *
                      inverse_norm[i];
    for (int j = k + 1; j < config.num_sections; ++j)
      gain *= section_norm[static_cast<std::size_t>(j)];
    bound += gain;
  }
  return bound;
}

}  // namespace flange::model
