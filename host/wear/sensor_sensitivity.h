// SPDX-License-Identifier: MIT
// How much the clearance reading moves per volt of sensor output, at a clearance: the slope of
// the calibration's regression d(V, T) at the voltage that reads that clearance, at the
// reference temperature. A sensor whose output voltage creeps (ageing, thesis 4.3) drifts in mm
// by this slope times the creep: the slope grows with the clearance (eq. 3.14's V^2 and V T
// terms), so the same creep in volts reads larger on a worn flange than on a new one.
#pragma once

#include <functional>

#include "calibration.h"

namespace flange::host {

// mm per V at a clearance in mm.
using SensitivityAt = std::function<double(double clearance_mm)>;

// From `calibration` at `temp_c`. The voltage is found by bisection over the calibrated voltage
// range widened by 1 V each side (the regression is monotonic there); a clearance outside it
// takes the slope at the nearer end.
SensitivityAt calibration_sensitivity(const Calibration& calibration, double temp_c);

}  // namespace flange::host
