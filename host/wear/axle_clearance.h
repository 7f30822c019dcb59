// SPDX-License-Identifier: MIT
// One run's static clearance of both wheels of an axle at reference conditions: the clearance
// the flange leaves with the wheelset centred on straight track and the sensor at the reference
// temperature, from the filtered clearance the chain wrote for each wheel.
//
// Left and right together: the wheelset's lateral shift x closes one gap and opens the other by
// as much (left = b_L - x, right = b_R + x), so their difference right - left = b_R - b_L + 2x
// shows where the wheelset runs, and their sum b_L + b_R is free of the shift. The route is
// mostly tangent (a curve shifts x one way only and covers less than half of a run), so the
// median of the difference is the centred wheelset's; the reference samples are those whose
// difference lies within kCentredToleranceMm of it. That also leaves out the curve's samples
// where a sensor sat on a rail of its range (a new flange's gap closes past the bottom of it).
// Over the reference samples the sum is fitted against the sensor temperature (least squares,
// sum = s0 + k (T - T_ref)) and taken at T_ref: what the calibration's temperature
// compensation left over (k) is removed. b_L = (s0 - d0) / 2, b_R = (s0 + d0) / 2 with d0 the
// reference samples' median difference.
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
  double difference_mm = 0.0;        // median of right - left
  double mean_temp_c = 0.0;
  std::size_t samples = 0;  // reference pairs used
};

// Reference temperature: the fleet's mean ambient (docs/fleet.md), inside the calibrated range.
inline constexpr double kReferenceTempC = 30.0;
// A pair is at the centred reference when its difference is within this of the median: the
// wheelset within 0.05 mm of its tangent position, as the alarms' 0.1 mm hysteresis is the
// smallest change of clearance that matters.
inline constexpr double kCentredToleranceMm = 0.1;

// Both wheels of one axle (the same number of samples, at least 2; NaN samples are left out).
// Nothing when fewer than two finite pairs remain.
std::optional<AxleClearance> axle_clearance(const WheelSamples& left, const WheelSamples& right,
                                            double reference_temp_c = kReferenceTempC);

// A wheel whose partner has no sensor: the median of its own clearance (the shift does not
// cancel; a curve-heavy run biases it).
std::optional<double> lone_wheel_clearance(const WheelSamples& wheel);

}  // namespace flange::host
