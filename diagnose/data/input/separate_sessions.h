// SPDX-License-Identifier: MIT
// Held-out data must be data the fit has not seen: not the calibration recording again, and not
// a stretch of time the calibration part covers.
#pragma once

#include "recording_series.h"

namespace flange::diagnose {

// Throws host::InputError (one line naming both recordings) when `heldout` is `calibration`
// again (the same file, or the same rows under another name), or when the two overlap in time on
// one clock: both start times given and their spans intersect, or, without start times, more
// than half of the held-out rows repeat calibration rows exactly (time, clearance, temperature
// and voltage: a stretch cut from the calibration recording; a separate session's noise makes
// such repeats rare).
void check_separate_sessions(const RecordingSeries& calibration, const RecordingSeries& heldout);

}  // namespace flange::diagnose
