// SPDX-License-Identifier: MIT
// The signature of mount motion in a gap: its variance follows the sensor's sensitivity squared.
#pragma once

#include <vector>

namespace flange::diagnose {

// vibration: mount motion reaches the voltage through the sensor's sensitivity dV/dd, so the
// gap's fast variance grows with (dV/dd)^2 while white voltage noise does not. Fits
// E[y] = a + b (dV/dd)^2 by least squares, first with y the squared first differences (motion
// white at fs), then, when that does not show it, with y the squared gap about its centred
// moving mean over 49 samples (motion whose aliases fall low: a narrow resonance, impacts).
struct VibrationSignature {
  double slope_t = 0.0;            // t statistic of b
  double rms_mm = 0.0;             // the motion's RMS: the larger of the two fits' estimates
  double voltage_noise_std_v = 0;  // the white voltage noise beside it (the differences' a / 2)
  bool present = false;  // slope_t > criteria::kMotionSlopeT, motion > kMotionLeastShare of it
};
// Where the micrometer rests for a quarter of the session or more, only samples at rest count:
// a bias that the picks leave changes where the clearance moves (a staircase's levels, a
// hysteresis that flips with the move), and with the sensitivity there it would pass for motion.
// Mount motion shakes the rests as much as the moves.
// `clearance_mm` empty: every sample counts.
VibrationSignature vibration_signature(const std::vector<double>& gap_v,
                                       const std::vector<double>& sensitivity_v_per_mm,
                                       const std::vector<double>& clearance_mm);

}  // namespace flange::diagnose
