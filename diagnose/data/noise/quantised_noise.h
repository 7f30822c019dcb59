// SPDX-License-Identifier: MIT
// The white noise behind a recording that a converter quantised coarsely. The median of
// differences collapses there (neighbouring samples share a code when the noise is below the
// LSB) or sits on the lattice of code steps; instead the noise is the maximum-likelihood fit of
// the code differences at a lag, given what the twin says the signal did over that lag, with
// the signal's place inside its cell taken as uniform: a difference of x LSB of analog signal
// plus noise shows as floor(x) or ceil(x) codes with the triangle weights 1 - frac(x), frac(x).
#pragma once

#include <cstddef>
#include <vector>

#include "adc_grid.h"

namespace flange::diagnose {

// The analog white noise's standard deviation (V) behind `recorded_v` on `grid`, where `twin_v`
// is the twin's noise-free voltage for the same samples. A 1 % share of differences may be
// anything (a clearance step the twin missed). Needs lag + 16 samples.
double quantised_noise_std(const std::vector<double>& recorded_v, const std::vector<double>& twin_v,
                           const AdcGrid& grid, std::size_t lag = 2);

// The RMS of (recorded - quantised twin) when white analog noise of `analog_std_v` is all that
// separates them: what an explained quantised recording leaves.
double quantised_null_rms(double analog_std_v, double lsb_v);

}  // namespace flange::diagnose
