// SPDX-License-Identifier: MIT
// The chain a recording's voltage passes after the sensor, as the stage gaps see it: the nominal
// model's compensation to clearance and the thesis's measurement filter.
#pragma once

#include <vector>

#include "polynomial_sensor_model.h"

namespace flange::diagnose {

// The thesis's measurement filter (eq. 4.15: Butterworth order 5, 0.574 Hz at 6 Hz), at the
// same cut-off relative to the recording's rate, in double precision, started from rest at the
// first input (a DC-settled state), so the start-up is not a gap.
std::vector<double> measurement_filter(const std::vector<double>& x, double fs_hz);

// The compensated clearance of voltages `v` at temperatures `t`: the nominal model inverted.
std::vector<double> clearance_of(const sim::PolynomialSensorModel& model,
                                 const std::vector<double>& v, const std::vector<double>& t);

}  // namespace flange::diagnose
