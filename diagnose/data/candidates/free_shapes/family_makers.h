// SPDX-License-Identifier: MIT
// How to make each free-shape family for a calibration part: what the classes' entries
// (candidates/class_fits.cpp, FreeShapeFamily::make) name. Each is defined beside its family.
#pragma once

#include <memory>

#include "family.h"
#include "recorded_part.h"

namespace flange::diagnose::free_shapes {

// Curves of one variable (curve_family.h).
std::unique_ptr<Family> make_temperature_offset_curve(const RecordedPart& calibration);
std::unique_ptr<Family> make_temperature_gain_curve(const RecordedPart& calibration);
// The same curves on kFineKnots, for a pick refitted finer (selection/free_refit.h).
std::unique_ptr<Family> make_fine_temperature_offset_curve(const RecordedPart& calibration);
std::unique_ptr<Family> make_fine_temperature_gain_curve(const RecordedPart& calibration);
std::unique_ptr<Family> make_voltage_curve(const RecordedPart& calibration);
std::unique_ptr<Family> make_clearance_curve(const RecordedPart& calibration);
std::unique_ptr<Family> make_settled_age_curve(const RecordedPart& calibration);
// A gain of temperature about a pivot of its own (pivot_gain_family.h).
std::unique_ptr<Family> make_pivot_gain(const RecordedPart& calibration);
// A surface over the top of the range (compression_surface_family.h).
std::unique_ptr<Family> make_compression_surface(const RecordedPart& calibration);
// A compression above a knee that moves with temperature (moving_knee_family.h).
std::unique_ptr<Family> make_moving_knee(const RecordedPart& calibration);
// A mix of lags and advances of the temperature (lag_family.h).
std::unique_ptr<Family> make_lag(const RecordedPart& calibration);
// Lags of the temperature in volts of their own (lag_family.h).
std::unique_ptr<Family> make_volts_lag(const RecordedPart& calibration);
// A skew of the voltage channel that drifts (skew_family.h).
std::unique_ptr<Family> make_skew(const RecordedPart& calibration);
// A periodic curve of the clearance (ripple_family.h).
std::unique_ptr<Family> make_clearance_ripple(const RecordedPart& calibration);
// A trend in the sensor's age that goes on (ageing_family.h).
std::unique_ptr<Family> make_continuing_ageing(const RecordedPart& calibration);
// A line in age held after the calibration session and a level between the sessions
// (ageing_level_family.h).
std::unique_ptr<Family> make_ageing_level(const RecordedPart& calibration);
// Lines at the aliases of the mains (mains_family.h).
std::unique_ptr<Family> make_mains_lines(const RecordedPart& calibration);

}  // namespace flange::diagnose::free_shapes
