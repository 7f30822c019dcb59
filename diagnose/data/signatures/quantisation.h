// SPDX-License-Identifier: MIT
// The converter, recognised when the voltages of both parts lie on one converter grid. The twin's
// converter on that grid is kept when it reproduces the recorded codes (what it leaves is within
// criteria::kExplainedRatio of what the noise alone would leave); when it does not (the thresholds
// sit elsewhere: a truncating converter, a gain or offset calibration in the DAQ software), the
// quantisation is taken as noise of LSB / sqrt(12), which the effective white noise already holds.
#pragma once

#include "parts.h"
#include "selection.h"
#include "white_noise.h"

namespace flange::diagnose {

// Sets selection.quantisation (with its own shrink: with the boundaries placed first, what placing
// them took off the held-out gap; else what the converter's replay takes) and quantised_on; when
// the twin's converter reproduces the codes, it joins `modelled` and replaces the placement's
// offset. A twin that holds the converter, or whose noise holds the rounding of this grid
// (`held_rounding_lsb_v`, sim::NoiseSettings::rounding_lsb_v, within criteria::kSameGridShare of
// its LSB), sets only quantised_on (and, for the latter, quantisation_as_noise): the grid is no
// finding again.
void recognise_quantisation(const Parts& parts, const WhiteNoise& white,
                            double held_rounding_lsb_v, Selection& selection);

}  // namespace flange::diagnose
