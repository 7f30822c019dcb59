// SPDX-License-Identifier: MIT
#include "smooth_function.h"

#include <algorithm>
#include <cmath>

namespace flange::third_reality {
namespace {

// Fritsch-Carlson: the harmonic mean of the neighbouring secants, zero at a local extremum.
std::vector<double> hermite_slopes(const SmoothFunction& f) {
  const std::size_t n = f.x.size();
  std::vector<double> secant(n - 1), slope(n, 0.0);
  for (std::size_t i = 0; i + 1 < n; ++i) secant[i] = (f.y[i + 1] - f.y[i]) / (f.x[i + 1] - f.x[i]);
  slope[0] = secant[0];
  slope[n - 1] = secant[n - 2];
  for (std::size_t i = 1; i + 1 < n; ++i) {
    if (secant[i - 1] * secant[i] <= 0.0) continue;
    const double w1 = 2.0 * (f.x[i + 1] - f.x[i]) + (f.x[i] - f.x[i - 1]);
    const double w2 = (f.x[i + 1] - f.x[i]) + 2.0 * (f.x[i] - f.x[i - 1]);
    slope[i] = (w1 + w2) / (w1 / secant[i - 1] + w2 / secant[i]);
  }
  return slope;
}

}  // namespace

void SmoothFunction::prepare() { slope = hermite_slopes(*this); }

double SmoothFunction::operator()(double u) const {
  if (u <= x.front()) return y.front();
  if (u >= x.back()) return y.back();
  const std::size_t i =
      static_cast<std::size_t>(std::upper_bound(x.begin(), x.end(), u) - x.begin()) - 1;
  const std::vector<double>& m = slope;
  const double h = x[i + 1] - x[i], s = (u - x[i]) / h;
  const double h00 = (1 + 2 * s) * (1 - s) * (1 - s), h10 = s * (1 - s) * (1 - s);
  const double h01 = s * s * (3 - 2 * s), h11 = s * s * (s - 1);
  return h00 * y[i] + h10 * h * m[i] + h01 * y[i + 1] + h11 * h * m[i + 1];
}

SmoothFunction draw_smooth_function(bool monotone, ThirdRandom& random) {
  const int knots = 3 + random.below(5);
  SmoothFunction f;
  f.x = {0.0, 1.0};
  for (int k = 2; k < knots; ++k) f.x.push_back(random.uniform(0.08, 0.92));
  std::sort(f.x.begin(), f.x.end());
  for (std::size_t k = 1; k < f.x.size(); ++k) f.x[k] = std::max(f.x[k], f.x[k - 1] + 0.05);
  for (double& v : f.x) v /= f.x.back();
  double level = 0.0;
  for (std::size_t k = 0; k < f.x.size(); ++k) {
    level = monotone ? level + random.uniform(0.1, 1.0) : random.uniform(-1.0, 1.0);
    f.y.push_back(level);
  }
  const auto [lo, hi] = std::minmax_element(f.y.begin(), f.y.end());
  const double low = *lo, span = std::max(*hi - *lo, 1e-9);
  const double direction = monotone ? random.sign() : 1.0;
  for (double& v : f.y) v = direction * (2.0 * (v - low) / span - 1.0);
  f.prepare();
  return f;
}

void put_smooth_function(const SmoothFunction& f, const std::string& prefix, Params& params) {
  params[prefix + "_n"] = static_cast<double>(f.x.size());
  for (std::size_t k = 0; k < f.x.size(); ++k) {
    params[prefix + "_x" + std::to_string(k)] = f.x[k];
    params[prefix + "_y" + std::to_string(k)] = f.y[k];
  }
}

SmoothFunction get_smooth_function(const Params& params, const std::string& prefix) {
  SmoothFunction f;
  const auto n = static_cast<std::size_t>(params.at(prefix + "_n"));
  for (std::size_t k = 0; k < n; ++k) {
    f.x.push_back(params.at(prefix + "_x" + std::to_string(k)));
    f.y.push_back(params.at(prefix + "_y" + std::to_string(k)));
  }
  f.prepare();
  return f;
}

}  // namespace flange::third_reality
