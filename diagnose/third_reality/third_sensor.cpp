// SPDX-License-Identifier: MIT
#include "third_sensor.h"

#include <algorithm>
#include <cmath>

namespace flange::third_reality {

double nominal_voltage(double clearance_mm, double coil_c) {
  // a V^2 + b V + (c - d) = 0 with a, b(T), c(T) from eq. 3.14.
  const double a = 0.05812;
  const double b = 0.3672 + 0.0006618 * coil_c;
  const double c = 1.16 - 0.0036 * coil_c - clearance_mm;
  const double disc = b * b - 4.0 * a * c;
  if (disc <= 0.0) return kRailLowV;
  const double v = (std::sqrt(disc) - b) / (2.0 * a);
  return std::clamp(v, kRailLowV, kRailHighV);
}

}  // namespace flange::third_reality
