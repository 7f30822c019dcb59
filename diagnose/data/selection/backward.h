// SPDX-License-Identifier: MIT
// The backward steps after the greedy forward ones: a pick taken first for what it explained alone
// can be made redundant by a later one (a static nonlinearity that took the calibration part's
// offset of a log-time ageing, which the refit handed back to the ageing).
#pragma once

#include <cstddef>

#include "parts.h"
#include "selection.h"

namespace flange::diagnose {

// Takes pick `j` out of the selection: its effect or free shape, with its finding and its round.
void remove_pick(Selection& selection, std::size_t j);

// A pick that the final model does not need (taking it out raises the held-out mean square by
// less than criteria::kRemovalMargin of sigma^2) is taken out, the least needed first, until every
// pick left is needed; each one taken out leaves a reason line (Selection::dropped).
void drop_unneeded_picks(const Parts& parts, Selection& selection);

}  // namespace flange::diagnose
