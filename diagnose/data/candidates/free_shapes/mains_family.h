// SPDX-License-Identifier: MIT
// The mains: tones at the aliases of 50 or 60 Hz and their harmonics (mains_lines.h). What
// carries from one session to the other is which lines are there; their amplitude and phase are
// fitted in every window of each part's own gap (FreeShapeFit::heldout_values says how many
// values that fits on the held-out part, which the selection charges against the gain), with
// each part's own constant where a harmonic aliases to 0 Hz. Not linear in values shared by the
// two parts, so it has a fit of its own (family.h).
#pragma once

#include <cstddef>
#include <vector>

#include "family.h"

namespace flange::diagnose::free_shapes {

class MainsFamily : public Family {
 public:
  // Finds the lines on the calibration gap, and the aliases they lie near.
  void search(const RecordedPart& calibration, const std::vector<double>& gap_v) override;
  FreeShapeFit fit(const FreeShapeInputs& in) override;

  bool empty() const { return tones_hz_.empty(); }
  // Lines were found, but their power followed the sensitivity: motion (line_source.h).
  bool lines_are_motion() const { return follow_sensitivity_; }
  std::size_t lines() const { return tones_hz_.size(); }
  // The lines found on the calibration part, Hz.
  const std::vector<double>& calibration_lines_hz() const { return cal_lines_; }
  // A harmonic of the lines' mains that aliases to 0 Hz (150 Hz at 6 Hz), Hz; 0 when none does.
  double dc_harmonic_hz() const { return dc_harmonic_hz_; }

 private:
  // The calibration's lines fitted window by window to its gap.
  std::vector<double> fitted_on_calibration(const RecordedPart& calibration,
                                            const std::vector<double>& gap_v) const;
  // Another part's own lines near the aliases kept, fitted window by window to `gap_v`;
  // `values` counts what that fits.
  std::vector<double> fitted(const RecordedPart& part, const std::vector<double>& gap_v,
                             int& values) const;
  void describe(FreeShapeFit& fit, const std::vector<double>& cal_tones_v) const;
  // The lines plus, where a harmonic of their mains lands on 0 Hz, the part's own constant.
  std::vector<double> with_session_constant(std::vector<double> tones,
                                            const std::vector<double>& gap_v) const;

  std::vector<double> tones_hz_;     // the aliases with a line on the calibration part
  std::vector<double> cal_lines_;    // the lines found there, Hz
  bool follow_sensitivity_ = false;  // lines were found, but their power followed dV/dd
  double dc_harmonic_hz_ = 0.0;
  double mains_hz_ = 0.0;  // 50 or 60: the mains whose harmonics' aliases hold the most lines
};

}  // namespace flange::diagnose::free_shapes
