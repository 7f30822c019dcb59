// SPDX-License-Identifier: MIT
// Whether a drift starts at its onset. A sensor's offset creeps from a day on: its series has no
// drift before the onset and a ramp after it, a kink at the onset. A wheel's own slow wander
// (its wear speeding up or slowing down for a spell, a leftover of the season that its sensor
// reads more than its partner's) is smooth, and the drift search's two terms from an onset fit
// it too, at a t and a size no locomotive's bar tells from a drift (sensor_drift.h), and in
// days as well as a change in km does (wear_change_in_km.h). What tells them apart is the
// kink: the same two terms from the series' first run (a smooth bend from the start, the same
// number of parameters) fit a wander about as well as from the onset, and a drift far worse.
// So the drift from its onset must fit its series better than the same terms from the first
// run by an F of at least kOnsetKinkT^2, widened for residuals correlated from run to run as
// the drift's standard error is (sensor_drift.h). A drift shows in both the axle's sum and its
// difference, the kink more sharply in one of them (the other also carries the partner's
// wander), so an axle's drift is flagged when either combination's candidate shows the kink.
// It is asked on a locomotive of kMinAxlesForTypical axles or more, as part of its bar
// (sensor_drift.h): the wanders it was set on are those of six-axle locomotives, and an axle
// alone has nothing to stand out from (a drift a few runs after a lathe pass, whose ramp the
// new flange's own rate takes most of, reaches a t of 6-10 and a kink of 5-9 on white noise).
#pragma once

#include "wear_line_fit.h"

namespace flange::host {

// The kink a drift's onset must show, as a t (the square root of the widened F). On the second
// fleet reality's 30 development fleets (9201-9255) the 13 healthy sensors the drift search
// flagged without it reach at most 7.6 (the sum of 9252 A02 axle 1), the drifts it flags at
// least 9.6 in one of their axle's two combinations, but for one (9202 A02 axle 1, 4.3: a
// wander of its own around the drift); on the first reality's 9101-9105 every drift at least
// 10.4. Nine: between the two, about as far from either.
inline constexpr double kOnsetKinkT = 9.0;

// sqrt(max(0, F)) with F = (rss_smooth - rss) / (rss / dof) / widening^2: `from_onset` is
// `series` fitted with a drift from its onset (wear_line_fit.h), rss_smooth the same fit with
// the drift's terms from the first run, `widening` how much wider than the run-to-run scatter
// the drift's standard error was taken (sqrt((1 + rho) / (1 - rho))). 0 without an onset.
double onset_kink_t(const WearSeries& series, const WearLineFit& from_onset, double widening);

}  // namespace flange::host
