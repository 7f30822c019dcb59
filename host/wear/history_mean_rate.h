// SPDX-License-Identifier: MIT
// A wheel's mean wear per km over its history: the wear its flanges gained from its first run to
// its last over the km run in between, the rate a depot books its slots on (and the one its
// truth is). The straight line's least-squares slope (wear_line_fit.h) is that only while the
// wear per km stays put: it weighs the runs by a parabola over the odometer, the middle of the
// history most and its ends least. When a locomotive's duties move the rate (a route, a season:
// its flanges wear faster for weeks at a time), the slope reads off alike on all its wheels, by
// up to 15 % on the second fleet reality (a locomotive whose flanges wore faster at both ends of
// the history than in its middle), and a share of 95 % intervals far under the level misses
// together, a locomotive at a time.
//
// So the wear is fitted as a continuous line broken at the starts of pieces of
// kRatePieceDays (one intercept per flange, as the straight line; one slope per piece):
//   y_k = a_seg(k) + r (km_k - km_0) + sum_j d_j max(0, km_k - E_j)
// E_j the odometer at piece j's first run, and the rate is the fitted line's rise from the first
// run to the last over the km between:
//   rate = r + sum_j d_j (km_last - E_j) / (km_last - km_first)
// a fixed contrast of the parameters, with the least-squares variance c^T (X^T X)^-1 c s^2. Its
// errors correlated from run to run are allowed by a delete-a-block jackknife of the rate
// (block_jackknife.h) over stretches kBlocksPerPiece to a piece, so that no stretch left out
// empties a piece (its slope would be free) and the refit keeps the same breaks, moderated by the
// fleet's wheels as the line's (moderated_spread.h). The forecast runs on at this rate from the
// straight line's clearance at the last run, with the line's uncertainty and its bend and season
// (fleet_wear.cpp, limit_forecast.h).
#pragma once

#include <optional>
#include <vector>

#include "block_jackknife.h"
#include "wear_line_fit.h"

namespace flange::host {

// A roster keeps a locomotive on a duty for weeks and changes it at a week's start; six weeks
// follow the moves of its rate that the straight line weighs unevenly, and leave each piece
// enough runs (30 or more) that its slope is not the runs' scatter.
inline constexpr double kRatePieceDays = 42.0;
// Jackknife stretches per piece: two weeks each. Fewer (a stretch a piece long) would empty a
// piece when left out; more would make them too short to hold the errors that last days (a spell
// of weather, a week's route).
inline constexpr int kBlocksPerPiece = 3;

struct HistoryMeanFit {
  WearSeries series;            // the wheel's series with the pieces' ramps in `shared`
  WearLineFit fit;              // its least-squares fit
  double rate_mm_per_km = 0.0;  // the fitted line's rise over the history's km
  double rate_se = 0.0;         // its least-squares standard error (the runs' own scatter)
  SerialSpread own_spread;      // its jackknife (inflation over rate_se^2)
  int pieces = 0;
};

// The history fit of a series without a drift fitted out (at least two runs a day apart); none
// when a piece or a flange's segment has too few runs to fix its parameters, or a stretch left
// out leaves too few for the refit (the wheel keeps the line's slope).
std::optional<HistoryMeanFit> history_mean_fit(const WearSeries& series);

// The fitted broken line at the series' run `k` (without the runs' scatter): the page draws it.
double history_fit_at(const HistoryMeanFit& history, std::size_t k);

}  // namespace flange::host
