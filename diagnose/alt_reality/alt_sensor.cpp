// SPDX-License-Identifier: MIT
#include "alt_sensor.h"

#include <algorithm>
#include <cmath>

namespace flange::alt_reality {
namespace {

// a V^2 + b(T) V + c(T) - d = 0.
constexpr double kA = 0.05812;
double linear_term(double coil_c) { return 0.3672 + 0.0006618 * coil_c; }
double constant_term(double coil_c) { return 1.16 - 0.0036 * coil_c; }

}  // namespace

double ideal_sensor_voltage(double clearance_mm, double coil_c) {
  const double b = linear_term(coil_c);
  const double c = constant_term(coil_c) - clearance_mm;
  const double discriminant = b * b - 4.0 * kA * c;
  if (discriminant < 0.0) return kSensorLowV;
  // The root with V >= 0 on the rising branch, written to avoid cancellation when c is small.
  const double root = -2.0 * c / (b + std::sqrt(discriminant));
  return std::clamp(root, kSensorLowV, kSensorHighV);
}

double ideal_sensor_slope_v_per_mm(double clearance_mm, double coil_c) {
  const double v = ideal_sensor_voltage(clearance_mm, coil_c);
  return 1.0 / (linear_term(coil_c) + 2.0 * kA * v);
}

}  // namespace flange::alt_reality
