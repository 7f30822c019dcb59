// SPDX-License-Identifier: MIT
// Inclusion: how often a pick would be made again on held-out resamples. The fits are not redone
// per resample: it is the scoring that is resampled.
#pragma once

#include <vector>

#include "block_resamples.h"
#include "parts.h"
#include "selection.h"

namespace flange::diagnose {

// The share of `resamples` on which `step`'s choice, or another candidate of its class, still
// wins and gains over `before`.
double share_of_wins(const Step& step, const std::vector<double>& before,
                     const BlockResamples& resamples);

// Each pick's inclusion: the share of its round's wins over resamples; where a pick was given a
// free shape after the rounds (the rounds' scores no longer add up to the final fit), the share
// of resamples on which the final fit without the pick leaves more.
void measure_inclusion(const Parts& parts, Selection& selection);

}  // namespace flange::diagnose
