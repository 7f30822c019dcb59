// SPDX-License-Identifier: MIT
// What makes a line the sampling folds onto a mains alias: pickup on the cable, whose amplitude
// does not change with the clearance or temperature, or mount motion, which reaches the voltage
// through the sensor's local sensitivity dV/dd (thesis eq. 3.14) and so grows and shrinks with it
// across the recording's clearance and temperature steps.
#pragma once

#include <cstddef>
#include <vector>

#include "recorded_part.h"

namespace flange::diagnose::free_shapes {

enum class LineSource {
  kMotion,  // its power follows (dV/dd)^2
  kPickup,  // it does not, where motion would have shown
  kEither,  // the sensitivity changes too little across the windows to tell
};

// A part and its gap, V.
struct PartGap {
  const RecordedPart& part;
  const std::vector<double>& gap_v;
};

struct LineSourceJudgement {
  LineSource source = LineSource::kEither;
  double slope_t = 0.0;     // t of the slope of the lines' window power on (dV/dd)^2
  double separation = 0.0;  // motion's slope (mean power / mean (dV/dd)^2) in standard errors
  std::size_t windows = 0;
};

// `lines_hz` fitted window by window (mains_lines.h) on each part's gap, their power in each
// window regressed on the window's mean (dV/dd)^2 over every part's windows
// (criteria::kMotionLineT, criteria::kLineSourceSeparation).
LineSourceJudgement line_source(const std::vector<PartGap>& parts,
                                const std::vector<double>& lines_hz);

}  // namespace flange::diagnose::free_shapes
