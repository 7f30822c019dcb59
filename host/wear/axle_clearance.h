// SPDX-License-Identifier: MIT
// One run's static clearance of both wheels of an axle at reference conditions: the clearance
// the flange leaves with the wheelset centred on straight track and the sensor at the reference
// temperature, from the filtered clearance the chain wrote for each wheel.
//
// Left and right together: the wheelset's lateral shift x closes one gap and opens the other by
// as much (left = b_L - x, right = b_R + x), so their difference right - left = b_R - b_L + 2x
// shows where the wheelset runs, and their sum b_L + b_R is free of the shift. The reference is
// the wheelset on tangent, and the tangent is found where the difference is densest: its
// half-sample mode (robust_location.h). A curve shifts the wheelset steadily to one side, a day's
// curves come in either hand in any mix, and on tangent the wheelset swings about its centre
// (the track's alignment, hunting). The median of the difference over the whole run is pulled
// towards the hand that has more curve that day, by a share of the tangent's swing, and both
// wheels' clearances with it in opposite directions (left and right errors correlated near -1,
// their sum unmoved); the mode is not, as long as the tangent holds more than half the run.
// The tangent's samples are those within kTangentSwingMm of the mode and the centre d0 is their
// median, taken again over the samples within kTangentSwingMm of it until it settles: the swing
// is about symmetric, and its median is steadier than the mode of one run.
// The reference samples are those within kCentredToleranceMm of d0; that also leaves out any
// curve sample where a sensor sat on a rail of its range (a new flange's gap closes past the
// bottom of it). Over them the sum is fitted against the sensor temperature (least squares,
// sum = s0 + k (T - T_ref)) and taken at T_ref: what the calibration's temperature
// compensation left over (k) is removed. b_L = (s0 - d0) / 2, b_R = (s0 + d0) / 2.
#pragma once

#include <optional>
#include <vector>

namespace flange::host {

// Samples of one wheel, after the filter's start-up: filtered clearance (mm) and temperature
// (degC) at the same instants as its axle partner's.
struct WheelSamples {
  std::vector<double> clearance_mm;
  std::vector<double> temp_c;
};

struct AxleClearance {
  double left_mm = 0.0;              // b_L at reference conditions
  double right_mm = 0.0;             // b_R
  double sum_mm = 0.0;               // s0: b_L + b_R at T_ref
  double temp_slope_mm_per_c = 0.0;  // k: the sum's leftover temperature dependence
  double difference_mm = 0.0;        // d0: the tangent's median of right - left
  double mean_temp_c = 0.0;
  std::size_t samples = 0;  // reference pairs used
};

// Reference temperature: the fleet's mean ambient (docs/fleet.md), inside the calibrated range.
inline constexpr double kReferenceTempC = 30.0;
// A pair is at the centred reference when its difference is within this of the median: the
// wheelset within 0.05 mm of its tangent position, as the alarms' 0.1 mm hysteresis is the
// smallest change of clearance that matters.
inline constexpr double kCentredToleranceMm = 0.1;
// A sample is on tangent when its difference is within this of the mode: a wheelset's swing on
// tangent of up to 0.15 mm either way (2x = 0.3 mm), where a curve's quasi-static shift pushes
// it 0.5 mm or more towards the outer rail (1 mm in the difference).
inline constexpr double kTangentSwingMm = 0.3;

// Both wheels of one axle (the same number of samples, at least 2; NaN samples are left out).
// Nothing when fewer than two finite pairs remain.
std::optional<AxleClearance> axle_clearance(const WheelSamples& left, const WheelSamples& right,
                                            double reference_temp_c = kReferenceTempC);

// A wheel whose partner has no sensor: the median of its own clearance (the shift does not
// cancel; a curve-heavy run biases it).
std::optional<double> lone_wheel_clearance(const WheelSamples& wheel);

}  // namespace flange::host
