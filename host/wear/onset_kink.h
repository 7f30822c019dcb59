// SPDX-License-Identifier: MIT
// Whether a drift starts at its onset. A sensor's offset creeps from a day on: its series has no
// drift before the onset and a ramp after it, a kink at the onset. A wheel's own slow wander
// (its wear speeding up or slowing down for a spell, a leftover of the season that its sensor
// reads more than its partner's) is smooth, and the drift search's two terms from an onset fit
// it too, at a t and a size no locomotive's bar tells from a drift (sensor_drift.h), and in
// days as well as a change in km does (wear_change_in_km.h). What tells them apart is the
// kink: a smooth bend from the series' first run (the drift's terms in the days since then, and
// one more power, as the onset is one more thing the search chose) fits a wander about as well
// as the drift from its onset, and a drift far worse. The kink is the ratio of the two fits'
// residual sums of squares, smooth over onset: scale-free, like the wander it is set against
// (a slow wander does not average out over more runs, as run-to-run scatter does). A drift
// shows in both the axle's sum and its difference, the kink more sharply in one of them (the
// other also carries the partner's wander), so an axle's drift is flagged when either
// combination's candidate shows it. It is asked on a locomotive of kMinAxlesForTypical axles or
// more, as part of its bar (sensor_drift.h): the wanders it was set on are six-axle
// locomotives', and an axle alone has nothing to be judged against (there the bar is the bare
// kDriftTStatistic as well). The price: a drift that starts a few runs after a lathe pass shows
// little kink, as the new flange's own intercept and rate start there too (new_flange_rates.h):
// on one axle with white noise (fleet_wear_test) its ratio stays under two, so on a locomotive
// such a drift is not flagged until it has grown away from the new flange's line.
#pragma once

#include "wear_line_fit.h"

namespace flange::host {

// The kink a drift's onset must show: the smooth bend leaves at least this many times the
// residual of the drift from its onset. On the second fleet reality's 30 development fleets
// (9201-9255, 5 locomotives x 120 days) the 13 healthy sensors the drift search flagged without
// it reach at most 1.91 (the sum of 9252 A02 axle 1), the 28 drifts it flags at least 2.25 in
// one of their axle's two combinations, and the first reality's drifts (9101-9105) at least
// 2.23: two is between them (1.9 leaves one healthy sensor flagged, 2.2 loses a drift).
inline constexpr double kOnsetKinkRatio = 2.0;
// A drift whose onset comes within this many days of the series' first run has too few runs
// before it for a bend from the first run to be told from it: such a drift is not judged on its
// kink (the flag's other bars still hold). The first reality draws its drifts' starts over the
// first third of the period; asked of those starting in its first week, the kink cost its
// held-out fleets 9341-9365 seven of their 42 drifts (docs/fleet.md, "Held-out figures"). The
// price: on the second reality's development fleets four of the 13 healthy sensors the kink
// cleared are flagged again, wanders the search starts in their first two weeks.
inline constexpr double kLeastDaysBeforeAKink = 14.0;

// rss_smooth / rss: `from_onset` is `series` fitted with a drift from its onset
// (wear_line_fit.h), rss_smooth the same fit with the drift's terms and one more power from the
// series' first run. Infinity when the smooth fit has too few runs, the onset comes within
// kLeastDaysBeforeAKink of the first run, or the drift fits exactly; 0 without an onset.
double onset_kink(const WearSeries& series, const WearLineFit& from_onset);

}  // namespace flange::host
