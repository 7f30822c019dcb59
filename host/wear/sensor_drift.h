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
// Each new flange (a lathe pass, a moved wheelset) has a rate of its own (new_flange_rates.h),
// and a drift must fit its series better as a change in days than the wear's own change in km
// fits it, both on top of each flange's bend (wear_change_in_km.h): a drift grows with days,
// depot days included, wear with km.
// The onset (and slope) with the smallest residual wins; the drift by the last run is a fault
// when it is both significant and large enough to matter, and it belongs to the sensor whose
// own series carries it more strongly (the other's has only what the two share).
//
// The same search runs on the axle's sum left + right. A wheelset's lateral position moves the
// two clearances by as much in opposite directions, so an error in where a run's centre is taken
// (a day of uneven curves) scatters the difference and cancels in the sum; the season's leftovers
// do the opposite. A drift shows in both, so it is looked for where it stands out: the series
// whose drift has the larger t. One sensor's drift moves the sum and the difference by as much,
// so a drift found in either must have moved the other (fitted with the same onset and slope)
// by at least half as much: a change both wheels share (a small lathe pass the data did not show
// as a jump) moves the sum alone, and where the wheelset runs between the rails the difference
// alone.
//
// What a drift is judged against. The series come with what every axle of the locomotive shares
// taken away (locomotive_common_mode.h). What is left still wanders slowly in a real fleet (a
// flange's wear speeding up as it thins, a wheel's own reaction to a route), and a drift search
// fits such a wander as well as a drift: the drift's standard error is widened for residuals
// correlated from run to run (an AR(1) error's (1 + rho) / (1 - rho)), and a drift must stand
// out from what the same search finds on a typical axle of its locomotive, by its t or by its
// size (LocomotiveBar): the other axles are the null a drift is judged against, whatever the
// wander of that locomotive's wear does to the statistic.
#pragma once

#include <optional>
#include <set>
#include <vector>

#include "wear_line_fit.h"

namespace flange::host {

// Terms of the drift in the time since the onset: linear and square (see above).
inline constexpr int kDriftDegree = 2;
// A drift is flagged when its value by the last run over its (widened) standard error reaches this. The onset
// search tries every run day, and a fleet has hundreds of sensors: a bound far in the normal tail
// keeps false flags below one in a fleet when the residuals are near normal.
inline constexpr double kDriftTStatistic = 6.0;
// ... and when it has moved the difference by at least this much (mm) by the last run: the
// smallest change that shifts an alarm decision (twice the alarms' default 0.1 mm hysteresis).
inline constexpr double kMinDriftMm = 0.2;
// ... and it stands out from its locomotive: what the axles show alike (a wiggle of the wear
// that a drift search takes for a drift, at a t the widening does not tame) is the
// locomotive's normal, and one sensor's drift is one axle of several standing out from it,
// either by its t, at least this many times the t half the axles reach with a drift-like fit
// of kMinDriftMm or more (a fit smaller than that is no drift whatever its t: the sum of a
// well-centred axle scatters so little that a bend of a few tenths of a mm reaches t = 30) ...
// Four: on the second fleet reality's development fleets (9201-9255, 30 fleets) a healthy
// sensor's bend of 0.2-0.7 mm passes three times the typical t on 7 of 1770 wheels that four
// times leaves unflagged, and no drift there or on the first reality's 9101-9315 needs less
// than four times (those it flags by t have more, or pass by their size).
inline constexpr double kDriftTOverTypical = 4.0;
// ... or by its size, at least this many times the size half the axles' drift-like fits reach
// (a drift of several mm on a locomotive whose wear wanders by tenths stands out whatever the
// wander does to its t).
inline constexpr double kDriftSizeOverTypical = 2.0;
// Those are taken over at least this many axles: with three, one drifting sensor's axle
// cannot move them past the other two.
inline constexpr std::size_t kMinAxlesForTypical = 3;
// An onset leaves at least this many runs after it, so that a drift is a trend, not one point,
inline constexpr std::size_t kMinRunsAfterOnset = 5;
// ... and has at least this many before it, so that a drift is a change: one from the first
// runs is the wheel's own rate as far as the data can tell.
inline constexpr std::size_t kMinRunsBeforeOnset = 5;

struct DriftFinding {
  bool left = true;              // the faulty sensor's side
  double onset_day = 0.0;        // days since 1970-01-01
  double rate_mm_per_day = 0.0;  // in its own series: the drift by the last run / the days
  double difference_t = 0.0;     // the drift by the last run / its standard error, in the
                                 // series it was found in (the difference or the sum)
  double size_mm = 0.0;          // |the difference's drift by the last run|
  bool in_sum = false;           // found in the axle's sum (else in its difference)
  bool moved_other = true;       // the other combination moved by at least half as much
  bool grows_with_days = true;   // its series is fitted better by a change in days than by
                                 // one in km (wear_change_in_km.h); compared only when its
                                 // size and t reach kMinDriftMm and kDriftTStatistic
};

// The best drift-like fit of each combination of the two wheels, before any threshold: its t
// and size say how far it stands out, and whether the other combination moved with it (see
// above).
struct DriftCandidates {
  std::optional<DriftFinding> in_difference, in_sum;
};

// `difference`, `left_series` and `right_series` share km, day and segments (their y: right -
// left, left, right); the side series carry their sensor's slope as drift_scale.
// `flange_starts`: the first run of each flange after the first (a lathe pass, a moved
// wheelset): each flange's bend is part of the wear a drift must explain better than
// (wear_change_in_km.h).
DriftCandidates drift_candidates(const WearSeries& difference, const WearSeries& left_series,
                                 const WearSeries& right_series,
                                 const std::set<std::size_t>& flange_starts = {});

// What a drift must reach on one locomotive to stand out from its axles: a t or a size.
struct LocomotiveBar {
  double t = kDriftTStatistic;
  double size_mm = kMinDriftMm;
};

// From each axle's candidates: kDriftTOverTypical times the t half the axles reach (each axle's
// larger |t| among its candidates of kMinDriftMm or more, 0 without any) and
// kDriftSizeOverTypical times the size half of them reach (each axle's larger size), each at
// least kDriftTStatistic and kMinDriftMm; with fewer than kMinAxlesForTypical axles, nothing to
// stand out from: a t of kDriftTStatistic is enough.
LocomotiveBar locomotive_bar(const std::vector<DriftCandidates>& axles);

// The candidate flagged as a sensor fault: its |t| at least kDriftTStatistic, its size at least
// kMinDriftMm, the other combination moved with it, and its |t| or its size at the bar; of two,
// the one with the larger t.
std::optional<DriftFinding> flagged_drift(const DriftCandidates& candidates,
                                          const LocomotiveBar& bar);

}  // namespace flange::host
