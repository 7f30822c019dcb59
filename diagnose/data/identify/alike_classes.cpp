// SPDX-License-Identifier: MIT
#include "alike_classes.h"

#include "aliased_lines.h"
#include "fixed_knees.h"
#include "gains_alike_offsets.h"

namespace flange::diagnose {

void judge_alike_classes(const Parts& parts, Selection& selection) {
  judge_aliased_lines(parts, selection);
  judge_fixed_knees(parts, selection);
  judge_gains_alike_offsets(parts, selection);
}

}  // namespace flange::diagnose
