// SPDX-License-Identifier: MIT
// What every axle of a locomotive shares, run by run. Its axles run the same km on the same
// track on the same days: the route's hand of curves (which flange the curves wear more, and
// where the day's wheelset centre lands), the season's leftovers of the temperature
// compensation, a spell of faster wear. Each axle's sum and difference are fitted with their own
// straight wear law (segments and a rate: wear_line_fit.h, the law the drift search fits, so
// no part of a shared bend is left behind in every axle) and what is left, run by run, is
// taken across the axles by its median: the part they share. One drifting sensor moves one axle of
// six, which the median does not follow, so a drift stands out once the shared part is taken
// away, and a shared wiggle (which a drift search on one axle alone would take for a drift)
// does not.
#pragma once

#include <cstdint>
#include <map>
#include <vector>

#include "wear_line_fit.h"

namespace flange::host {

// The median is taken over at least this many axles having the run: with three, one drifting
// sensor cannot move it past the other two.
inline constexpr std::size_t kMinAxlesForCommonMode = 3;

// One axle's runs: their ids and the axle's sum left + right and difference right - left.
struct AxleSeries {
  std::vector<std::int64_t> run_id;
  WearSeries sum, difference;
};

// Per run id, the shared part of the sum and of the difference (mm); a run fewer than
// kMinAxlesForCommonMode axles have is missing (nothing to take away there).
struct CommonMode {
  std::map<std::int64_t, double> sum_mm, difference_mm;
};

CommonMode locomotive_common_mode(const std::vector<AxleSeries>& axles);

// `series` (one axle's, with those run ids) with the shared part at each run taken away.
WearSeries without_common_mode(WearSeries series, const std::vector<std::int64_t>& run_id,
                               const std::map<std::int64_t, double>& shared);

// `series` with the two shared shapes (the sum's and the difference's, 0 where a run has none)
// as regressors of their own (WearSeries::shared), each fitted with this axle's coefficient.
// The route's curving, the season and a spell of faster wear multiply each wheel's own rate,
// so an axle that wears faster than the locomotive's median carries more of the shared wander
// than the median took away, and one that wears slower less: taken away at coefficient 1 the
// rest is left as a bend that a drift search fits. Two shapes, because the route's hand of
// curves moves the left and the right flanges' wear apart (left = (sum - difference) / 2,
// right = (sum + difference) / 2: any mix of the two sides' wander is in their span). One
// drifting sensor moves one axle, which the median does not follow, so the drift is not in them.
// A shape none of the axle's runs has is left out.
WearSeries with_shared_shapes(WearSeries series, const std::vector<std::int64_t>& run_id,
                              const CommonMode& common);

}  // namespace flange::host
