// SPDX-License-Identifier: MIT
// How far the held-out gap shrinks once the selected effects are added: overall, in the
// where-cell and in the where-band.
#pragma once

#include "findings.h"
#include "locate.h"
#include "recording_series.h"
#include "selection.h"

namespace flange::diagnose {

// The verdict's held-out figures (`from_verdict`: its worst window and the samples within the
// calibration's ranges) with the overall, where-cell and where-band figures added; `where` is the
// gap located on the calibration part.
HowFar measure_how_far(const RecordingSeries& heldout, const Selection& selection,
                       const Location& where, HowFar from_verdict);

}  // namespace flange::diagnose
