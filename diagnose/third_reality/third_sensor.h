// SPDX-License-Identifier: MIT
// The third reality's nominal sensor: the thesis's calibration eq. 3.14,
// d = 1.16 + 0.3672 V - 0.0036 T + 0.05812 V^2 + 0.0006618 V T, read as a quadratic in V and
// solved by the quadratic formula (the root on the rising branch), held to the 0-10 V supply.
#pragma once

namespace flange::third_reality {

inline constexpr double kRailLowV = 0.0;
inline constexpr double kRailHighV = 10.0;

// The voltage of an ideal sensor at `clearance_mm` and coil temperature `coil_c`, in
// [kRailLowV, kRailHighV].
double nominal_voltage(double clearance_mm, double coil_c);

}  // namespace flange::third_reality
