// SPDX-License-Identifier: MIT
// What a calibration part holds constant, or visits at too few values to fit a law of it: the
// verdict on such data says what one operating point (or a line through two) can tell, and the
// stages that look for structure in time and frequency have none to find.
#pragma once

#include <string>
#include <vector>

#include "recording_series.h"

namespace flange::diagnose {

struct DegenerateData {
  bool clearance_constant = false;
  bool temperature_constant = false;
  bool voltage_constant = false;
  bool noise_zero = false;
  std::vector<std::string> sentences;  // one per finding, for Diagnosis::degenerate
  // Whether the gap has no structure in time or frequency to locate (the voltage constant, or no
  // noise to measure structure against): the band and the change points are then left out.
  bool nothing_to_locate() const { return voltage_constant || noise_zero; }
};

// `calibration`'s inputs, and the white-noise estimate `noise_std_v` (V) of its gap: a variable
// with one distinct value is constant; one with fewer than criteria::kLeastDistinctValues cannot
// carry a law of it (a curve through two points is a line); a noise estimate of exactly zero
// means the recorded voltage repeats to its last decimal.
DegenerateData degenerate_data(const RecordingSeries& calibration, double noise_std_v);

}  // namespace flange::diagnose
