// SPDX-License-Identifier: MIT
// Measures of how the fixed-point core departs from its double-precision reference, and of what
// it does on its own (limit cycles under zero input).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "filter_json.h"

namespace flange::model {

// 10 log10(sum ref^2 / sum (test - ref)^2) over equal-length sequences; +inf when they agree.
// Throws std::invalid_argument on a length mismatch or an all-zero reference.
double snr_db(const std::vector<double>& reference, const std::vector<double>& test);

// Largest |test - reference| over equal-length sequences.
double max_abs_error(const std::vector<double>& reference, const std::vector<double>& test);

// What the tail of a zero-input response settles into.
struct LimitCycle {
  bool decays_to_zero = false;  // the tail is all zeros
  std::int32_t amplitude = 0;   // max |y| over the tail, in LSB
  std::size_t period = 0;       // smallest p with y[n] = y[n - p] over the whole tail (0: none)
  std::int32_t minimum = 0, maximum = 0;  // range of the tail, in LSB
  std::size_t settled_after = 0;  // index of the first sample of the periodic (or zero) tail
  std::string describe() const;   // one line for logs and docs
};

// Examines y[y.size() - tail ..]: tail >= 2 * max_period so that a period is seen twice.
LimitCycle find_limit_cycle(const std::vector<std::int32_t>& y, std::size_t tail,
                            std::size_t max_period);

// A rigorous bound, in LSB, on the zero-input output of the core once the response to the
// initial state has died away (any limit cycle or dead band). Section k rounds its y_ext with an
// error of at most 1/2 a y_ext LSB (2^-s sample LSB), fed back through 1 - E_k(z) and 1/A_k, and
// truncates its lo phase by less than one accumulator LSB (2^-(s+F) sample LSB), which circulates
// through 1/A_k alone; both reach the output through the sections after k, and sample_o adds its
// own rounding of at most 1/2 LSB:
//   |y| <= 1/2 + sum_k (2^-(s+1) ||(1 - E_k)/A_k||_1 + 2^-(s+F) ||1/A_k||_1)
//                      prod_{j>k} ||B_j/A_j||_1,
// with the quantised words. The l1 norms are summed in double until the impulse responses have
// decayed below 1e-13.
double limit_cycle_bound_lsb(const CoreConfig& config);

}  // namespace flange::model
