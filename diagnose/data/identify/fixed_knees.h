// SPDX-License-Identifier: MIT
// A compression whose knee does not move and a static nonlinearity of V (docs/diagnose.md,
// "Confidence"): above a knee that stays put over the recorded temperatures, a range
// compression's family fits a curve of the voltage alone, which the selection names a
// nonlinearity; a range compression whose knee is fixed is that same curve, so no data of these
// temperatures can tell the two apart, and the pick names both.
#pragma once

#include <string>

#include "parts.h"
#include "selection.h"

namespace flange::diagnose {

// Each pick whose free shape a range compression's family made, but which names another class
// (FreeShapeFit::also_of_class: its knee or surface did not move with temperature), names that
// family's class in its indistinguishable_from (criteria::kMostConfidenceOfIndistinguishable then
// bounds its confidence).
void judge_fixed_knees(Selection& selection);

// What would tell the pick's curve from a compression of the class `other`: a session that holds
// the clearance where the voltage lies above the knee while the temperature goes beyond the
// recorded range (a compression's knee may move there, a nonlinearity of V does not); or, where
// the recordings already span the bench's operating range, that no session of it would.
std::string tell_fixed_knee_from_compression(const Parts& parts, const EffectFinding& pick,
                                             const std::string& other);

}  // namespace flange::diagnose
