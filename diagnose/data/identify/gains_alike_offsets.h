// SPDX-License-Identifier: MIT
// A gain alike an offset curve of the temperature (docs/diagnose.md, "Indistinguishable
// classes"): a gain about a pivot far off the recorded voltages, (V - p) h(T), changes with the
// voltage by a small share of its level, so a curve of the recorded temperature alone may follow
// it as closely as the data can tell; the pick then names the offset's class too.
#pragma once

#include <string>

#include "parts.h"
#include "selection.h"

namespace flange::diagnose {

// Each pick whose free shape's family names a class it may equally be when a curve of the
// temperature alone follows it (FreeShapeFamily::temperature_alone_also_of) and such a curve does
// (curve_of_one_variable_alike, on the recorded temperature with free_shapes::kKnots knots, the
// offset family's, on the held-out samples within the calibration part's ranges) names that class
// in its indistinguishable_from (criteria::kMostConfidenceOfIndistinguishable then bounds its
// confidence).
void judge_gains_alike_offsets(const Parts& parts, Selection& selection);

// What would tell the pick's gain from an offset of the class `other`: longer sessions sweeping
// the clearance over the whole range at each temperature (a gain scales with the voltage's
// distance from its pivot, an offset does not).
std::string tell_gain_from_offset(const EffectFinding& pick, const std::string& other);

}  // namespace flange::diagnose
