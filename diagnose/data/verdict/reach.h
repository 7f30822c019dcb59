// SPDX-License-Identifier: MIT
// Where on the held-out part the fitted curves are interpolated (within the calibration's
// clearance and temperature ranges) and where they are continued or held beyond them, and what is
// left in the held-out windows within reach.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "calibration_reach.h"
#include "findings.h"
#include "recording_series.h"

namespace flange::diagnose {

// The held-out window where `error` has the largest RMS. The windows split the held-out samples
// within the calibration's reach (criteria::kLocalWindows of them, at least
// criteria::kLeastLocalWindowSamples each): beyond those ranges a curve is continued or held, and
// what it leaves there says how well it guessed, not that something else is there.
HeldoutWindow worst_window(const RecordingSeries& heldout, const CalibrationReach& reach,
                           const std::vector<double>& error);

// The share of a gap's RMS above `noise` that the selected effects take: from `rms_before` to
// `rms_after` (0 when the gap is not above the noise).
double above_noise_share_taken(double rms_before, double rms_after, double noise);

}  // namespace flange::diagnose
