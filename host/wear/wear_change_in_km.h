// SPDX-License-Identifier: MIT
// Whether a change is the sensor's (in days) or the wear's (in km). A flange need not wear at
// one rate all its life: on the second fleet reality it wears faster as it thins (its clearance
// bends upward in km over its life), and a spell of the route or the season moves one axle's
// wear more than the locomotive's shared shapes take away (its rate changes from some run on).
// The drift search's linear and square terms in days from an onset fit such a change of the
// wear as well as a drift wherever the km per day are steady, at a t and a size the bar of
// sensor_drift.h does not tell from a drift. What tells them apart is what each grows with: a
// sensor's drift with days, depot days and short days included; wear with km. So a drift is
// flagged only when the series is fitted better (a smaller residual sum of squares) by a change
// in days than by a change in km, both on top of the same wear: each flange's own bend
// ((km - km at its first run)^2 on its runs: wear that speeds up as the flange thins bends the
// clearance over the flange's life, from its first run), and each searched over the drift
// search's onsets with two terms (days since the onset and its square through the sensor's
// slope, as the drift search fits them; km since the onset and its square). Both have the same
// number of parameters, so the smaller residual is the comparison, with no margin to set.
// On the second reality's 30 development fleets 9201-9255 it takes the healthy sensors
// flagged from 25 to 13 of 1770 with the same 28 of 30 drifts, and changes
// nothing on the first reality's 9101-9105, 9301-9305 and 9311-9315 (19 of 20 drifts, no
// healthy sensor); docs/fleet.md, step 4.
#pragma once

#include <cstddef>
#include <set>

#include "wear_line_fit.h"

namespace flange::host {

// A bend needs this many runs on its flange to be told from the flange's intercept and rate.
inline constexpr std::size_t kMinRunsForBend = 3;

// `series` with one more regressor (WearSeries::shared) per flange: (km - km at the flange's
// first run)^2, in (1000 km)^2, on that flange's runs and 0 elsewhere. `flange_starts`: the first
// run of each flange after the first (index 0 starts the first); a flange of fewer than
// kMinRunsForBend runs gets none.
WearSeries with_flange_bends(WearSeries series, const std::set<std::size_t>& flange_starts);

// What a change from an onset grows with: days (a sensor's drift: the drift terms of
// wear_line_fit.h through the series' drift_scale) or km (the wear's own change: the km since
// the onset and its square, in 1000 km).
enum class ChangeIn { days, km };

// The smallest residual sum of squares of `series` with each flange's bend and a change in
// `in` from one run on, over the onsets with at least `runs_before` runs before and more than
// `runs_after` after; `drift_degree` terms for a change in days. Infinity when none fits.
double best_change_rss(const WearSeries& series, const std::set<std::size_t>& flange_starts,
                       ChangeIn in, int drift_degree, std::size_t runs_before,
                       std::size_t runs_after);

}  // namespace flange::host
