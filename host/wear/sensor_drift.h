// SPDX-License-Identifier: MIT
// A sensor drifting away from its axle partner. Both wheels of an axle run the same km on the
// same track at the same temperature, so whatever the two share (the season, the calibration's
// leftovers) cancels in their difference right - left; what is left is the two flanges'
// different wear, which grows with distance, and a sensor's drift, which grows with time
// (whether the locomotive runs or stands in the depot). The difference is fitted with segments
// and a rate per km (wear_line_fit.h), then again with a drift per day from each candidate
// onset; the best onset's drift is a fault when it is both significant and large enough to
// matter. The faulty sensor is the one whose own series carries the drift more strongly.
#pragma once

#include <optional>
#include <vector>

#include "wear_line_fit.h"

namespace flange::host {

// A drift is flagged when |g| / se(g) reaches this. The onset search tries every run day, and a
// fleet has hundreds of sensors: a bound far in the normal tail keeps false flags below one in
// a fleet when the residuals are near normal.
inline constexpr double kDriftTStatistic = 6.0;
// ... and when it has moved the difference by at least this much (mm) by the last run: the
// smallest change that shifts an alarm decision (twice the alarms' default 0.1 mm hysteresis).
inline constexpr double kMinDriftMm = 0.2;
// An onset leaves at least this many runs after it, so that a drift is a trend, not one point.
inline constexpr std::size_t kMinRunsAfterOnset = 5;

struct DriftFinding {
  bool left = true;            // the faulty sensor's side
  double onset_day = 0.0;      // days since 1970-01-01
  double rate_mm_per_day = 0.0;  // in its own series
  double difference_t = 0.0;   // g / se(g) in the difference
  double size_mm = 0.0;        // the drift by the last run
};

// `difference`, `left_series` and `right_series` share km, day and segments (their y: right -
// left, left, right). Nothing when no onset gives a flagged drift.
std::optional<DriftFinding> find_sensor_drift(const WearSeries& difference,
                                              const WearSeries& left_series,
                                              const WearSeries& right_series);

}  // namespace flange::host
