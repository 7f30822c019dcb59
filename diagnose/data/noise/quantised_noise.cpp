// SPDX-License-Identifier: MIT
#include "quantised_noise.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace flange::diagnose {
namespace {

constexpr double kOutlierShare = 0.01;

double normal_cdf(double z) { return 0.5 * std::erfc(-z / std::numbers::sqrt2); }
double normal_pdf(double z) { return std::exp(-0.5 * z * z) / std::sqrt(2.0 * std::numbers::pi); }

// E[tri(D + c)] for D ~ N(0, s^2) and the triangle tri(y) = max(0, 1 - |y|): the probability
// that a difference of c LSB of signal plus noise D shows as a code difference of 0 (shift c
// by -m for m codes).
double triangle_probability(double c, double s) {
  if (s < 1e-9) return std::max(0.0, 1.0 - std::abs(c));
  // Integrals of the N(c, s^2) density and of y times it over [a, b].
  const auto mass = [&](double a, double b) {
    return normal_cdf((b - c) / s) - normal_cdf((a - c) / s);
  };
  const auto moment = [&](double a, double b) {
    return c * mass(a, b) + s * (normal_pdf((a - c) / s) - normal_pdf((b - c) / s));
  };
  return moment(-1.0, 0.0) + mass(-1.0, 0.0) + mass(0.0, 1.0) - moment(0.0, 1.0);
}

struct CodeSteps {
  std::vector<double> offset;  // signal change less the code change, in LSB
  double outlier_probability = 0.0;
};

// The code steps at `lag`, leaving out pairs that touch the lowest or highest code used: there
// a converter or the sensor may sit on its rail, where the code does not follow the signal.
CodeSteps code_steps(const std::vector<double>& recorded_v, const std::vector<double>& twin_v,
                     const AdcGrid& grid, std::size_t lag) {
  const double lsb = grid.lsb_v;
  const auto on_rail = [&](double v) {
    return v < grid.lowest_v + 0.5 * lsb || v > grid.highest_v - 0.5 * lsb;
  };
  CodeSteps steps;
  double widest = 1.0;
  for (std::size_t i = 0; i + lag < recorded_v.size(); ++i) {
    if (on_rail(recorded_v[i]) || on_rail(recorded_v[i + lag])) continue;
    const double codes = std::round((recorded_v[i + lag] - recorded_v[i]) / lsb);
    const double signal = (twin_v[i + lag] - twin_v[i]) / lsb;
    steps.offset.push_back(signal - codes);
    widest = std::max(widest, std::abs(signal - codes));
  }
  steps.outlier_probability = 1.0 / (2.0 * std::ceil(widest) + 1.0);
  return steps;
}

// Minus the log-likelihood of noise r (in LSB) for the code steps.
double negative_log_likelihood(const CodeSteps& steps, double r) {
  const double s = std::numbers::sqrt2 * r;  // a difference of two samples' noise
  double sum = 0.0;
  for (const double c : steps.offset) {
    const double p = (1.0 - kOutlierShare) * triangle_probability(c, s) +
                     kOutlierShare * steps.outlier_probability;
    sum -= std::log(std::max(p, 1e-300));
  }
  return sum;
}

// The minimiser of f over [lo, hi] in log r: the best of a coarse lattice, then golden section
// in the cells beside it.
double minimise_in_log(const std::function<double(double)>& f, double lo, double hi) {
  constexpr int kLattice = 24;
  const double a = std::log(lo), b = std::log(hi), cell = (b - a) / kLattice;
  int best = 0;
  double best_value = std::numeric_limits<double>::infinity();
  for (int k = 0; k <= kLattice; ++k) {
    const double value = f(std::exp(a + k * cell));
    if (value < best_value) {
      best_value = value;
      best = k;
    }
  }
  double left = a + std::max(best - 1, 0) * cell, right = a + std::min(best + 1, kLattice) * cell;
  const double golden = 0.5 * (std::sqrt(5.0) - 1.0);
  double x1 = right - golden * (right - left), x2 = left + golden * (right - left);
  double f1 = f(std::exp(x1)), f2 = f(std::exp(x2));
  for (int i = 0; i < 30; ++i) {
    if (f1 < f2) {
      right = x2;
      x2 = x1;
      f2 = f1;
      x1 = right - golden * (right - left);
      f1 = f(std::exp(x1));
    } else {
      left = x1;
      x1 = x2;
      f1 = f2;
      x2 = left + golden * (right - left);
      f2 = f(std::exp(x2));
    }
  }
  return std::exp(0.5 * (left + right));
}

}  // namespace

double quantised_noise_std(const std::vector<double>& recorded_v, const std::vector<double>& twin_v,
                           const AdcGrid& grid, std::size_t lag) {
  if (recorded_v.size() != twin_v.size() || recorded_v.size() < lag + 16) {
    throw std::invalid_argument("quantised_noise_std: too few or unequal samples");
  }
  const CodeSteps steps = code_steps(recorded_v, twin_v, grid, lag);
  if (steps.offset.size() < 16) return 0.0;
  const auto f = [&](double r) { return negative_log_likelihood(steps, r); };
  return grid.lsb_v * minimise_in_log(f, 1e-3, 50.0);
}

double quantised_null_rms(double analog_std_v, double lsb_v) {
  // E over the noise of sum_m m^2 tri(x - m), x = noise / lsb: the mean square code error of
  // quantising signal plus noise against quantising the signal alone (place in cell uniform).
  const double r = analog_std_v / lsb_v;
  if (r < 1e-9) return 0.0;
  constexpr int kNodes = 400;
  const double span = 8.0 * r, dx = 2.0 * span / kNodes;
  double mean_square = 0.0;
  for (int k = 0; k <= kNodes; ++k) {
    const double x = -span + k * dx;
    const double frac = std::abs(x) - std::floor(std::abs(x));
    const double lo = std::floor(std::abs(x)), hi = lo + 1.0;
    const double weight = (k == 0 || k == kNodes ? 0.5 : 1.0) * normal_pdf(x / r) / r * dx;
    mean_square += weight * ((1.0 - frac) * lo * lo + frac * hi * hi);
  }
  return lsb_v * std::sqrt(mean_square);
}

}  // namespace flange::diagnose
