// SPDX-License-Identifier: MIT
#include "calibration_reach.h"

#include <algorithm>

namespace flange::diagnose {

CalibrationReach calibration_reach(const RecordingSeries& calibration,
                                   const RecordingSeries& heldout) {
  CalibrationReach reach;
  const auto [t_lo, t_hi] =
      std::minmax_element(calibration.temp_c.begin(), calibration.temp_c.end());
  const auto [x_lo, x_hi] =
      std::minmax_element(calibration.clearance_mm.begin(), calibration.clearance_mm.end());
  reach = {*t_lo, *t_hi, *x_lo, *x_hi, {}, {}};
  for (std::size_t i = 0; i < heldout.size(); ++i) {
    const bool within = heldout.temp_c[i] >= reach.temp_lo_c &&
                        heldout.temp_c[i] <= reach.temp_hi_c &&
                        heldout.clearance_mm[i] >= reach.clearance_lo_mm &&
                        heldout.clearance_mm[i] <= reach.clearance_hi_mm;
    (within ? reach.heldout_within : reach.heldout_beyond).push_back(i);
  }
  return reach;
}

}  // namespace flange::diagnose
