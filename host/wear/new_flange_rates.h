// SPDX-License-Identifier: MIT
// A new flange's own rate in the drift search. A flange need not wear at one rate all its life:
// on the second fleet reality it wears faster as it thins, so after a lathe pass the new flange
// wears about a quarter slower than the old one did, and a wheelset moved in from another axle
// brings its own rate. With one rate over both flanges the drift search reads the bend from the
// change on as a drift: on that reality's development fleets (9201-9255) 31 of the 36 healthy
// sensors it flagged were on wheels reprofiled in the period, the onset at the lathe pass or a
// bend of the thinning flange before it. So each flange of the axle gets a rate of its own from
// its first run, in the axle's sum and difference and in each wheel's own series alike (a lathe
// pass turns both wheels, a move brings both). A drift still shows: it grows with days, depot
// days included, where a rate grows with km, and it moves one sensor where a new flange moves
// both. On those fleets this flags 25 healthy sensors of 1770 instead of 36, with the same 28 of
// 30 drifts, and changes nothing on the first reality's 9101-9315 (19 of 20 drifts, no healthy
// sensor); a sensor replacement is not a new flange and gets no rate of its own.
#pragma once

#include <cstddef>
#include <set>

#include "wear_line_fit.h"

namespace flange::host {

// `series` with one more regressor (WearSeries::shared) per index in `first_runs`, the first run
// on a new flange: the km run since that run, 0 before it. Index 0 (the first flange's rate is
// the series' own), one past the end and one with no km run after it are left out.
WearSeries with_new_flange_rates(WearSeries series, const std::set<std::size_t>& first_runs);

}  // namespace flange::host
