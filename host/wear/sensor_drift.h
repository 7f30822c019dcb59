// SPDX-License-Identifier: MIT
// A sensor drifting away from its axle partner. Both wheels of an axle run the same km on the
// same track at the same temperature, so whatever the two share (the season, the calibration's
// leftovers) cancels in their difference right - left; what is left is the two flanges'
// different wear, which grows with distance, and a sensor's drift, which grows with time
// (whether the locomotive runs or stands in the depot). A sensor drifts in its output voltage
// (its offset creeps, thesis 4.3), which reads in mm through the sensor's slope at the
// clearance of the day (sensor_sensitivity.h). The difference is fitted with segments, a rate
// per km and a drift m_k (g tau + g2 tau^2) (wear_line_fit.h), m_k the slope of the left or of
// the right sensor, from each candidate onset: the creep is linear in volts, and the square term
// takes what the slope at the day's reading misses (the reading itself moves with the creep).
// The onset (and slope) with the smallest residual wins; the drift by the last run is a fault
// when it is both significant and large enough to matter, and it belongs to the sensor whose
// own series carries it more strongly (the other's has only what the two share).
//
// The same search runs on the axle's sum left + right. A wheelset's lateral position moves the
// two clearances by as much in opposite directions, so an error in where a run's centre is taken
// (a day of uneven curves) scatters the difference and cancels in the sum; the season's leftovers
// do the opposite. A drift shows in both, so it is looked for where it stands out: the series
// whose drift has the larger t. A drift found in the sum must have moved the difference (fitted
// with the same onset and slope) by at least half as much: a change both wheels share (a small
// lathe pass the data did not show as a jump) moves the sum alone.
#pragma once

#include <optional>
#include <vector>

#include "wear_line_fit.h"

namespace flange::host {

// Terms of the drift in the time since the onset: linear and square (see above).
inline constexpr int kDriftDegree = 2;
// A drift is flagged when its value by the last run over its standard error reaches this. The onset
// search tries every run day, and a fleet has hundreds of sensors: a bound far in the normal tail
// keeps false flags below one in a fleet when the residuals are near normal.
inline constexpr double kDriftTStatistic = 6.0;
// ... and when it has moved the difference by at least this much (mm) by the last run: the
// smallest change that shifts an alarm decision (twice the alarms' default 0.1 mm hysteresis).
inline constexpr double kMinDriftMm = 0.2;
// An onset leaves at least this many runs after it, so that a drift is a trend, not one point.
inline constexpr std::size_t kMinRunsAfterOnset = 5;

struct DriftFinding {
  bool left = true;              // the faulty sensor's side
  double onset_day = 0.0;        // days since 1970-01-01
  double rate_mm_per_day = 0.0;  // in its own series: the drift by the last run / the days
  double difference_t = 0.0;     // the drift by the last run / its standard error, in the
                                 // series it was found in (the difference or the sum)
  double size_mm = 0.0;          // |the difference's drift by the last run|
  bool in_sum = false;           // found in the axle's sum (else in its difference)
};

// `difference`, `left_series` and `right_series` share km, day and segments (their y: right -
// left, left, right); the side series carry their sensor's slope as drift_scale. Nothing when
// no series, side and onset give a flagged drift.
std::optional<DriftFinding> find_sensor_drift(const WearSeries& difference,
                                              const WearSeries& left_series,
                                              const WearSeries& right_series);

}  // namespace flange::host
