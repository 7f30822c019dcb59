// SPDX-License-Identifier: MIT
#include "axle_clearance.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <tuple>

#include "robust_location.h"

namespace flange::host {
namespace {

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

// The median of the differences within kTangentSwingMm of a centre, from the mode on, until it
// settles: the mode of one run can sit at one end of the swing (a swing spends most of its time
// at its ends), and each step takes in more of the swing's other side while the window is wider
// than the swing.
double tangent_centre(const std::vector<double>& differences) {
  double centre = half_sample_mode(differences);
  for (int step = 0; step < 20; ++step) {
    std::vector<double> tangent;
    for (const double d : differences) {
      if (std::abs(d - centre) <= kTangentSwingMm) tangent.push_back(d);
    }
    const double next = median(tangent);
    if (std::abs(next - centre) < 1e-6) return next;
    centre = next;
  }
  return centre;
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
  const double centre = tangent_centre(differences);
  std::vector<double> ref_sums, ref_temps;
  for (std::size_t i = 0; i < sums.size(); ++i) {
    if (std::abs(differences[i] - centre) > kCentredToleranceMm) continue;
    ref_sums.push_back(sums[i]);
    ref_temps.push_back(temps[i]);
  }
  if (ref_sums.size() < 2) return std::nullopt;
  AxleClearance axle;
  std::tie(axle.sum_mm, axle.temp_slope_mm_per_c) = line_at(ref_temps, ref_sums, reference_temp_c);
  axle.difference_mm = centre;
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
