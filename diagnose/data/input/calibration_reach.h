// SPDX-License-Identifier: MIT
// Which held-out samples lie within the calibration part's clearance and temperature ranges: there
// a curve fitted on the calibration is interpolated, beyond them it is continued or held. The
// verdict judges what the picks leave within reach (verdict/reach.h); the ageing's level between
// the sessions is measured there (candidates/free_shapes/ageing_level_family.h).
#pragma once

#include <cstddef>
#include <vector>

#include "recording_series.h"

namespace flange::diagnose {

// The held-out samples whose clearance and temperature lie within the calibration part's ranges,
// in time order, and the others.
struct CalibrationReach {
  double temp_lo_c = 0.0, temp_hi_c = 0.0, clearance_lo_mm = 0.0, clearance_hi_mm = 0.0;
  std::vector<std::size_t> heldout_within;
  std::vector<std::size_t> heldout_beyond;
};

CalibrationReach calibration_reach(const RecordingSeries& calibration,
                                   const RecordingSeries& heldout);

}  // namespace flange::diagnose
