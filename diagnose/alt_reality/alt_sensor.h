// SPDX-License-Identifier: MIT
// The alternative reality's nominal sensor: the thesis's calibration eq. 3.14,
// d = 1.16 + 0.3672 V - 0.0036 T + 0.05812 V^2 + 0.0006618 V T, solved for V in closed form
// (it is a quadratic in V) rather than by the twin's root finder, with the output held to the
// sensor's 0-10 V supply range.
#pragma once

namespace flange::alt_reality {

inline constexpr double kSensorLowV = 0.0;
inline constexpr double kSensorHighV = 10.0;

// The voltage an ideal sensor outputs at `clearance_mm` and coil temperature `coil_c`, clamped
// to [kSensorLowV, kSensorHighV].
double ideal_sensor_voltage(double clearance_mm, double coil_c);

// dV/dd of the ideal sensor at that point (V/mm): how mount motion shows in volts.
double ideal_sensor_slope_v_per_mm(double clearance_mm, double coil_c);

}  // namespace flange::alt_reality
