// SPDX-License-Identifier: MIT
#include "reference_filter.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace flange::model {

ReferenceFilter::ReferenceFilter(const FloatDesign& design, Form form)
    : form_(form), gain_(design.leftover_gain) {
  if (form_ == Form::kSos) {
    for (const auto& row : design.sos) {
      const double a0 = row[3];
      b_.push_back({row[0] / a0, row[1] / a0, row[2] / a0});
      a_.push_back({1.0, row[4] / a0, row[5] / a0});
    }
  } else {
    const double a0 = design.a[0];
    std::vector<double> b, a;
    for (double v : design.b) b.push_back(v / a0);
    for (double v : design.a) a.push_back(v / a0);
    b_.push_back(b);
    a_.push_back(a);
  }
  reset();
}

ReferenceFilter::ReferenceFilter(std::vector<std::vector<double>> b,
                                 std::vector<std::vector<double>> a, double gain)
    : form_(Form::kSos), gain_(gain), b_(std::move(b)), a_(std::move(a)) {
  reset();
}

ReferenceFilter ReferenceFilter::quantized(const CoreConfig& config, double leftover_gain) {
  std::vector<std::vector<double>> b, a;
  for (int k = 0; k < config.num_sections; ++k) {
    b.push_back(config.b_values(k));
    a.push_back(config.a_values(k));
  }
  return ReferenceFilter(std::move(b), std::move(a), leftover_gain);
}

std::complex<double> ReferenceFilter::response(double f_over_fs) const {
  // Each stage's b(z) / a(z) at z = e^(j 2 pi f / fs), in powers of z^-1.
  const std::complex<double> z_inverse = std::polar(1.0, -2.0 * std::numbers::pi * f_over_fs);
  const auto polynomial = [&](const std::vector<double>& c) {
    std::complex<double> sum = 0.0;
    for (auto it = c.rbegin(); it != c.rend(); ++it) sum = sum * z_inverse + *it;
    return sum;
  };
  std::complex<double> h = gain_;
  for (std::size_t k = 0; k < b_.size(); ++k) h *= polynomial(b_[k]) / polynomial(a_[k]);
  return h;
}

void ReferenceFilter::reset() {
  x_.clear();
  y_.clear();
  for (std::size_t k = 0; k < b_.size(); ++k) {
    x_.emplace_back(b_[k].size(), 0.0);
    y_.emplace_back(a_[k].size(), 0.0);
  }
}

double ReferenceFilter::step(double x) {
  double v = x;
  for (std::size_t k = 0; k < b_.size(); ++k) {
    std::vector<double>& xs = x_[k];
    std::vector<double>& ys = y_[k];
    std::rotate(xs.rbegin(), xs.rbegin() + 1, xs.rend());
    xs[0] = v;
    double acc = 0.0;
    for (std::size_t i = 0; i < b_[k].size(); ++i) acc += b_[k][i] * xs[i];
    // ys[0] is the previous output until this stage's new one is stored.
    std::rotate(ys.rbegin(), ys.rbegin() + 1, ys.rend());
    for (std::size_t j = 1; j < a_[k].size(); ++j) acc -= a_[k][j] * ys[j];
    ys[0] = acc;
    v = acc;
  }
  return gain_ * v;
}

}  // namespace flange::model
