// SPDX-License-Identifier: MIT
// Mount motion, recognised from its signature in both parts (vibration_signature.h).
#pragma once

#include <vector>

#include "block_resamples.h"
#include "parts.h"
#include "selection.h"
#include "findings.h"

namespace flange::diagnose {

// The share of `resamples` of the held-out gap on which the vibration signature still shows.
double vibration_inclusion(const std::vector<double>& gap, const TwinReplay& replay,
                           const RecordingSeries& series, const BlockResamples& resamples);

// The motion's mean square in mm^2 on a part, from what is left there, regressed over the whole
// part: the squared departures from its mean against the sensitivity squared, E = a + b (dV/dd)^2,
// b. (The signature's levels are taken about a moving mean of 49 samples, which takes with it the
// part of the motion that the sampling aliases below about 0.1 Hz: a narrow resonance near a
// multiple of fs.) Over the part a slow bias left by the picks would count as motion too, so this
// counts only when the regression splits what is left into the noise and the motion: a, the part
// not following the sensitivity, between half the noise variance and `white_allowed` squared (a
// hysteresis the picks left, whose size grows faster than (dV/dd)^2, gives a < 0). 0 otherwise.
double motion_mean_square_over_part(const std::vector<double>& left,
                                    const std::vector<double>& sensitivity_v_per_mm, double sigma,
                                    double white_allowed);

// Sets selection.vibration when both parts show the signature. Returns the noise the verdict
// compares what is left with: the white voltage noise, or, with mount motion found, that plus the
// motion's share, whose variance follows the sensitivity and so escapes the median-based estimate.
VerdictNoise recognise_vibration(const Parts& parts, Selection& selection);

}  // namespace flange::diagnose
