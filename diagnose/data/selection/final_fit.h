// SPDX-License-Identifier: MIT
// The selection's final fit read pick by pick: the held-out gap with some picks left out.
#pragma once

#include <cstddef>
#include <vector>

#include "parts.h"
#include "selection.h"

namespace flange::diagnose {

// The held-out gap that the picks marked in `kept` leave (the twin's own effects and the
// converter's placed boundaries always in), each with its parameters from the final fit; the
// library's effects stay in the order they were fitted in.
std::vector<double> heldout_error_with(const Parts& parts, const Selection& selection,
                                       const std::vector<bool>& kept);

// The held-out gap's RMS with every pick but pick `j`.
double heldout_rms_without(const Parts& parts, const Selection& selection, std::size_t j);

// Each pick as the final fit has it, in the order the rounds took them: the held-out gap's RMS
// with every pick but this one (what the final model needs it for), and its before and after with
// the picks listed before it (what the refits and the backward steps left of each round's own
// figures). The order stays the greedy one: a constant offset is shared between classes as the
// fits happen to split it (an ageing's offset against a nonlinearity curve's level), so a ranking
// by that need would follow the split, not the data.
void measure_picks_in_final_fit(const Parts& parts, Selection& selection);

}  // namespace flange::diagnose
