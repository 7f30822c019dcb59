// SPDX-License-Identifier: MIT
#include "reference_filter.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <utility>

namespace flange::model {

namespace {

// Stages with M and the stage count fixed at compile time: biquads and first-order stages, up to
// this many. Everything else (the direct form, longer cascades) runs the general loop.
constexpr int kMaxFixedStages = 8;

}  // namespace

// The sos rows, or the whole b/a as one stage, normalised so that a[0] = 1.
ReferenceFilter::BA ReferenceFilter::stages_of(const FloatDesign& design, Form form) {
  std::vector<std::vector<double>> b, a;
  if (form == Form::kSos) {
    for (const auto& row : design.sos) {
      const double a0 = row[3];
      b.push_back({row[0] / a0, row[1] / a0, row[2] / a0});
      a.push_back({1.0, row[4] / a0, row[5] / a0});
    }
  } else {
    const double a0 = design.a[0];
    b.emplace_back();
    a.emplace_back();
    for (double v : design.b) b.back().push_back(v / a0);
    for (double v : design.a) a.back().push_back(v / a0);
  }
  return {std::move(b), std::move(a)};
}

ReferenceFilter::ReferenceFilter(const FloatDesign& design, Form form)
    : ReferenceFilter(stages_of(design, form), design.leftover_gain) {}

ReferenceFilter::ReferenceFilter(BA stages, double gain)
    : gain_(gain), stages_(static_cast<int>(stages.first.size())) {
  auto& [b, a] = stages;
  for (std::size_t k = 0; k < b.size(); ++k) {
    order_ = std::max(order_, static_cast<int>(std::max(b[k].size(), a[k].size())) - 1);
  }
  // Zero terms add +0.0 to the sum: the same value as leaving them out.
  const auto m = static_cast<std::size_t>(order_);
  for (std::size_t k = 0; k < b.size(); ++k) {
    b[k].resize(m + 1, 0.0);
    a[k].resize(m + 1, 0.0);
    coef_.insert(coef_.end(), b[k].begin(), b[k].end());
    coef_.insert(coef_.end(), a[k].begin() + 1, a[k].end());
  }
  const auto pick = [this]<int kOrder>() -> BlockRun {
    switch (stages_) {
      case 1:
        return &ReferenceFilter::run<kOrder, 1>;
      case 2:
        return &ReferenceFilter::run<kOrder, 2>;
      case 3:
        return &ReferenceFilter::run<kOrder, 3>;
      case 4:
        return &ReferenceFilter::run<kOrder, 4>;
      case 5:
        return &ReferenceFilter::run<kOrder, 5>;
      case 6:
        return &ReferenceFilter::run<kOrder, 6>;
      case 7:
        return &ReferenceFilter::run<kOrder, 7>;
      case 8:
        return &ReferenceFilter::run<kOrder, 8>;
      default:
        return &ReferenceFilter::run<0, 0>;
    }
  };
  static_assert(kMaxFixedStages == 8, "one case per fixed stage count");
  block_run_ = order_ == 2   ? pick.template operator()<2>()
               : order_ == 1 ? pick.template operator()<1>()
                             : &ReferenceFilter::run<0, 0>;
  reset();
}

ReferenceFilter ReferenceFilter::quantized(const CoreConfig& config, double leftover_gain) {
  std::vector<std::vector<double>> b, a;
  for (int k = 0; k < config.num_sections; ++k) {
    b.push_back(config.b_values(k));
    a.push_back(config.a_values(k));
  }
  return ReferenceFilter({std::move(b), std::move(a)}, leftover_gain);
}

std::complex<double> ReferenceFilter::response(double f_over_fs) const {
  // Each stage's b(z) / a(z) at z = e^(j 2 pi f / fs), in powers of z^-1.
  const std::complex<double> z_inverse = std::polar(1.0, -2.0 * std::numbers::pi * f_over_fs);
  const int m = order_;
  std::complex<double> h = gain_;
  for (int k = 0; k < stages_; ++k) {
    const double* const b = coef_.data() + k * (2 * m + 1);
    const double* const a = b + m;  // a[1..M]
    std::complex<double> num = 0.0, den = 0.0;
    for (int i = m; i >= 0; --i) {
      num = num * z_inverse + b[i];
      den = den * z_inverse + (i == 0 ? 1.0 : a[i]);
    }
    h *= num / den;
  }
  return h;
}

void ReferenceFilter::reset() {
  history_.assign(static_cast<std::size_t>((stages_ + 1) * order_), 0.0);
}

// Moves a line one place older: `newest` becomes age 1.
template <int kOrder>
static inline void push_line(double* line, int m, double newest) {
  const int order = kOrder > 0 ? kOrder : m;
  for (int age = order; age > 1; --age) line[age - 1] = line[age - 2];
  if (order > 0) line[0] = newest;
}

template <int kOrder, int kStages>
void ReferenceFilter::run(const double* in, double* out, std::size_t n) {
  constexpr bool kFixed = kOrder > 0;
  const int m = kFixed ? kOrder : order_;
  const int stages = kFixed ? kStages : stages_;
  const int words = 2 * m + 1;
  // With M and the stage count fixed, the words and the history live in local arrays the
  // compiler keeps in registers; otherwise the members are used in place.
  std::array<double, kFixed ? kStages*(2 * kOrder + 1) : 1> local_coef{};
  std::array<double, kFixed ? (kStages + 1) * kOrder : 1> local_history{};
  const double* coef = coef_.data();
  double* hist = history_.data();
  if constexpr (kFixed) {
    std::copy(coef_.begin(), coef_.end(), local_coef.begin());
    std::copy(history_.begin(), history_.end(), local_history.begin());
    coef = local_coef.data();
    hist = local_history.data();
  }

  double v = 0.0;  // the stage's input: x, then each stage's output
  const auto stage = [&](int k) __attribute__((always_inline)) {
    const double* const b = coef + k * words;  // b[0..M]
    const double* const a = b + m;             // a[1..M] at a[1..M]
    double* const xs = hist + k * m;           // the stage's inputs of ages 1..M
    const double* const ys = xs + m;           // its outputs of ages 1..M (the next line)
    // The older terms first, then the input (the stage before's output of this sample), and
    // the stage's own last output last: its recursion, which bounds the rate, is one product and
    // one subtraction; the input's path through a stage a product and two additions.
    double older = 0.0;
    for (int i = m; i >= 1; --i) older += b[i] * xs[i - 1];
    for (int j = m; j >= 2; --j) older -= a[j] * ys[j - 1];
    const double with_input = older + b[0] * v;
    push_line<kOrder>(xs, m, v);  // the next line is still read by the next stage, as inputs
    v = m >= 1 ? with_input - a[1] * ys[0] : with_input;
  };
  for (std::size_t i = 0; i < n; ++i) {
    v = in[i];
    if constexpr (kFixed) {
      // Unrolled, so that every index is a constant and the arrays can live in registers.
      [&]<int... k>(std::integer_sequence<int, k...>) { (stage(k), ...); }
      (std::make_integer_sequence<int, kStages>{});
    } else {
      for (int k = 0; k < stages; ++k) stage(k);
    }
    push_line<kOrder>(hist + stages * m, m, v);
    out[i] = gain_ * v;
  }

  if constexpr (kFixed) std::copy(local_history.begin(), local_history.end(), history_.begin());
}

double ReferenceFilter::step(double x) {
  double y;
  run<0, 0>(&x, &y, 1);  // the general loop on the members in place
  return y;
}

void ReferenceFilter::process(std::span<const double> in, std::span<double> out) {
  if (in.size() != out.size()) {
    throw std::invalid_argument(
        fmt::format("ReferenceFilter::process: {} inputs but {} outputs", in.size(), out.size()));
  }
  (this->*block_run_)(in.data(), out.data(), in.size());
}

}  // namespace flange::model
