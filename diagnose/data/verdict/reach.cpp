// SPDX-License-Identifier: MIT
#include "reach.h"

#include <algorithm>

#include "criteria.h"
#include "series_arithmetic.h"
#include "series_statistics.h"

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

HeldoutWindow worst_window(const RecordingSeries& heldout, const CalibrationReach& reach,
                           const std::vector<double>& error) {
  const std::vector<std::size_t>& within = reach.heldout_within;
  const std::size_t n = within.size();
  const std::size_t length =
      std::max(n / criteria::kLocalWindows, criteria::kLeastLocalWindowSamples);
  HeldoutWindow worst;
  for (std::size_t begin = 0; begin + length <= n; begin += length) {
    const auto window = std::span(within).subspan(begin, length);
    const double rms = rms_at(error, window);
    if (rms > worst.rms_v) worst = {heldout.t_s[window.front()], heldout.t_s[window.back()], rms};
  }
  return worst;
}

double above_noise_share_taken(double rms_before, double rms_after, double noise) {
  const double before = rms_above_noise(rms_before, noise);
  if (before <= 0.0) return 0.0;
  return 1.0 - rms_above_noise(rms_after, noise) / before;
}

}  // namespace flange::diagnose
