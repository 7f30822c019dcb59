// SPDX-License-Identifier: MIT
// A converter's code boundaries need not sit where rounding puts them: a truncating one puts them
// a whole LSB up, which offsets every code by -LSB/2 against the twin's rounding. On a coarse grid
// that offset is as large as an effect, and a bias class would take it before the quantisation is
// recognised. So when both parts lie on one grid, the twin's converter on it is replayed with its
// boundaries at 21 places over [-0.5, 0.5] LSB (threshold_lsb), the place that fits the
// calibration part best is kept, and the mean offset it gives the twin's voltage there joins the
// twin as a constant before any effect is fitted (a constant, not the converter itself, so that
// the effects' fits stay smooth). With it, a DAQ gain calibration the grid shows
// (AdcGrid::calibration_gain): the recorded voltage is then the gain times the twin's, plus a
// constant, of which only the constant is fitted.
#pragma once

#include <optional>
#include <vector>

#include "effect_catalogue.h"
#include "parts.h"

namespace flange::diagnose {

struct ConverterPlacement {
  double threshold_lsb = 0.0;  // where the boundaries sit against rounding's, LSB
  double offset_v = 0.0;       // the mean offset they give the twin's voltage
  // The DAQ's gain calibration, when placed with them, and its constant.
  std::optional<double> gain;
  double gain_offset_v = 0.0;
  // What the placement adds to the twin's voltage on each part.
  std::vector<double> cal_added_v, ho_added_v;
};

// The placement on the parts' shared grid, when they lie on one, the effects `modelled` do not
// hold the converter already, and it lowers the calibration gap's mean square by
// criteria::kConverterPlacementGain of `noise_v` squared (the gain calibration likewise).
std::optional<ConverterPlacement> place_converter_boundaries(
    const Parts& parts, const std::vector<sim::EffectSettings>& modelled, double noise_v);

}  // namespace flange::diagnose
