// SPDX-License-Identifier: MIT
// Brent's bracketing root finder: it never leaves the bracket (bisection is its fallback) and
// converges superlinearly on smooth functions, which the sensor model inversion needs per sample.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace flange::sim {

// Returns x in [lo, hi] with f(x) = 0 to within `x_tolerance` (> 0). f_lo = f(lo) and
// f_hi = f(hi) must not have the same sign (throws std::invalid_argument otherwise).
template <typename Function>
double brent_root(const Function& f, double lo, double hi, double f_lo, double f_hi,
                  double x_tolerance) {
  if (f_lo == 0.0) return lo;
  if (f_hi == 0.0) return hi;
  if ((f_lo > 0.0) == (f_hi > 0.0)) throw std::invalid_argument("brent_root: no sign change");
  double a = lo;  // previous iterate
  double fa = f_lo;
  double b = hi;  // best estimate
  double fb = f_hi;
  double c = a;  // the root lies between b and c
  double fc = fa;
  double step = b - a;
  double previous_step = step;
  constexpr int kMaxIterations = 200;  // bisection alone halves [0, 10] V to 1e-13 in 47
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    if ((fb > 0.0) == (fc > 0.0)) {
      c = a;
      fc = fa;
      step = previous_step = b - a;
    }
    if (std::abs(fc) < std::abs(fb)) {
      a = b;
      b = c;
      c = a;
      fa = fb;
      fb = fc;
      fc = fa;
    }
    const double tolerance =
        2.0 * std::numeric_limits<double>::epsilon() * std::abs(b) + 0.5 * x_tolerance;
    const double half_interval = 0.5 * (c - b);
    if (std::abs(half_interval) <= tolerance || fb == 0.0) return b;
    if (std::abs(previous_step) >= tolerance && std::abs(fa) > std::abs(fb)) {
      // Secant (two points) or inverse quadratic interpolation (three points).
      const double s = fb / fa;
      double p = 0.0;
      double q = 0.0;
      if (a == c) {
        p = 2.0 * half_interval * s;
        q = 1.0 - s;
      } else {
        const double qa = fa / fc;
        const double r = fb / fc;
        p = s * (2.0 * half_interval * qa * (qa - r) - (b - a) * (r - 1.0));
        q = (qa - 1.0) * (r - 1.0) * (s - 1.0);
      }
      if (p > 0.0) {
        q = -q;
      } else {
        p = -p;
      }
      // Accept the interpolation only if it stays well inside the bracket and shrinks fast.
      if (2.0 * p < std::min(3.0 * half_interval * q - std::abs(tolerance * q),
                             std::abs(previous_step * q))) {
        previous_step = step;
        step = p / q;
      } else {
        step = previous_step = half_interval;
      }
    } else {
      step = previous_step = half_interval;
    }
    a = b;
    fa = fb;
    b += std::abs(step) > tolerance ? step : (half_interval > 0.0 ? tolerance : -tolerance);
    fb = f(b);
  }
  return b;
}

}  // namespace flange::sim
