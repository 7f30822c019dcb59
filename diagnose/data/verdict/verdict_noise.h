// SPDX-License-Identifier: MIT
// What the held-out gap that is left is compared with, and why when it is not the white noise.
#pragma once

#include <string>

#include "findings.h"
#include "selection.h"
#include "white_noise.h"

namespace flange::diagnose {

// With the converter's grid modelled, what is left is compared with what the noisy twin leaves
// once quantised on that grid (quantised_noise.h): less than the white noise when the noise is
// below the LSB, sqrt(sigma^2 + LSB^2 / 6) when it is far above. With the quantisation taken as
// noise, the white noise already holds its LSB^2 / 12.
VerdictNoise with_converter_grid(const Selection& selection, const WhiteNoise& white,
                                 VerdictNoise noise);

}  // namespace flange::diagnose
