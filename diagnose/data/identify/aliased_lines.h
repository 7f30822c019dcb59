// SPDX-License-Identifier: MIT
// Mains pickup and mount motion folded by the sampling onto one line of the recording
// (docs/diagnose.md, "Aliased lines"): motion moves the voltage by the sensor's sensitivity dV/dd,
// which changes with clearance and temperature, and pickup does not; where dV/dd does not change
// enough to tell, the mains pick names motion as a class the data cannot tell from it.
#pragma once

#include <string>
#include <vector>

#include "parts.h"
#include "selection.h"

namespace flange::diagnose {

// The lines a mains pick puts in the recording at `fs_hz`: a free shape's own (`line_hz_k`), or
// the aliases of a library pick's harmonics that show as lines (free_shapes::mains_aliases).
std::vector<double> mains_pick_lines_hz(const EffectFinding& finding, double fs_hz);

// Each mains pick with a line (a group of lines near one alias) whose window power over both
// parts' gaps is not shown to be pickup (free_shapes::line_source: it follows (dV/dd)^2, or the
// data could not have shown that it does not) names mount motion in its indistinguishable_from.
// A line that follows dV/dd is motion, but the pick's other lines may be pickup: the selection
// kept them as one pick, so both classes are named rather than the pick dropped.
void judge_aliased_lines(const Parts& parts, Selection& selection);

// What would tell the pick's line from motion: a sample rate at which its mains harmonics fold
// away from every frequency of motion that folds onto the line (separating_rate.h), or a session
// whose clearance steps change dV/dd.
std::string tell_line_from_motion(const Parts& parts, const EffectFinding& pick,
                                  const std::string& motion);

}  // namespace flange::diagnose
