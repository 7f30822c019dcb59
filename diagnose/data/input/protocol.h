// SPDX-License-Identifier: MIT
// What a session's micrometer protocol lets the data tell apart.
#pragma once

#include "recording_series.h"

namespace flange::diagnose {

// Whether, in `s`, the direction of the last clearance move is set by the clearance itself: in
// every band of a criteria::kProtocolBands-th of the range holding
// criteria::kLeastSamplesPerProtocolBand or more samples at rest after the first move, at least
// criteria::kOneWayShare of them were last reached by a move the same way, and both ways occur (a
// staircase that climbs in steps and drops back in one move). Then an output that depends on the
// direction of the last move is a function of clearance. A sweep says no: it reaches each
// clearance from both sides; it slows to rest only at its turning points, where each band is
// reached one way, so a micrometer that rests for less than a quarter of the session is not asked
// (pairs_at_rest returns nothing).
bool last_move_set_by_clearance(const RecordingSeries& s);

}  // namespace flange::diagnose
