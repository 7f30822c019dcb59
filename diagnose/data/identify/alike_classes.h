// SPDX-License-Identifier: MIT
// Every check of a pick that the data cannot tell from another class (docs/diagnose.md,
// "Indistinguishable classes"), in turn: a mains line alike mount motion (aliased_lines.h), a
// curve over the top alike a compression or a nonlinearity (fixed_knees.h), a gain alike an
// offset curve of the temperature (gains_alike_offsets.h).
#pragma once

#include "parts.h"
#include "selection.h"

namespace flange::diagnose {

void judge_alike_classes(const Parts& parts, Selection& selection);

}  // namespace flange::diagnose
