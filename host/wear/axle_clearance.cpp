// SPDX-License-Identifier: MIT
#include "axle_clearance.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <tuple>

namespace flange::host {
namespace {

double median(std::vector<double> values) {
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  if (values.size() % 2 == 1) return *middle;
  return (*middle + *std::max_element(values.begin(), middle)) / 2.0;
}

// Least-squares line y = a + k (x - x0); a flat temperature gives k = 0 and a = mean(y).
std::pair<double, double> line_at(const std::vector<double>& x, const std::vector<double>& y,
                                  double x0) {
  double mean_x = 0.0, mean_y = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    mean_x += x[i];
    mean_y += y[i];
  }
  mean_x /= static_cast<double>(x.size());
  mean_y /= static_cast<double>(y.size());
  double sxx = 0.0, sxy = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sxx += (x[i] - mean_x) * (x[i] - mean_x);
    sxy += (x[i] - mean_x) * (y[i] - mean_y);
  }
  const double slope = sxx > 0.0 ? sxy / sxx : 0.0;
  return {mean_y + slope * (x0 - mean_x), slope};
}

}  // namespace

std::optional<AxleClearance> axle_clearance(const WheelSamples& left, const WheelSamples& right,
                                            double reference_temp_c) {
  std::vector<double> sums, differences, temps;
  const std::size_t n = std::min(left.clearance_mm.size(), right.clearance_mm.size());
  for (std::size_t i = 0; i < n; ++i) {
    const double l = left.clearance_mm[i], r = right.clearance_mm[i];
    const double t = (left.temp_c[i] + right.temp_c[i]) / 2.0;
    if (!std::isfinite(l) || !std::isfinite(r) || !std::isfinite(t)) continue;
    sums.push_back(l + r);
    differences.push_back(r - l);
    temps.push_back(t);
  }
  if (sums.size() < 2) return std::nullopt;
  const double centre = median(differences);
  std::vector<double> ref_sums, ref_differences, ref_temps;
  for (std::size_t i = 0; i < sums.size(); ++i) {
    if (std::abs(differences[i] - centre) > kCentredToleranceMm) continue;
    ref_sums.push_back(sums[i]);
    ref_differences.push_back(differences[i]);
    ref_temps.push_back(temps[i]);
  }
  if (ref_sums.size() < 2) return std::nullopt;
  AxleClearance axle;
  std::tie(axle.sum_mm, axle.temp_slope_mm_per_c) = line_at(ref_temps, ref_sums, reference_temp_c);
  axle.difference_mm = median(ref_differences);
  axle.left_mm = (axle.sum_mm - axle.difference_mm) / 2.0;
  axle.right_mm = (axle.sum_mm + axle.difference_mm) / 2.0;
  double temp_sum = 0.0;
  for (const double t : ref_temps) temp_sum += t;
  axle.mean_temp_c = temp_sum / static_cast<double>(ref_temps.size());
  axle.samples = ref_sums.size();
  return axle;
}

std::optional<double> lone_wheel_clearance(const WheelSamples& wheel) {
  std::vector<double> finite;
  for (const double c : wheel.clearance_mm) {
    if (std::isfinite(c)) finite.push_back(c);
  }
  if (finite.empty()) return std::nullopt;
  return median(finite);
}

}  // namespace flange::host
