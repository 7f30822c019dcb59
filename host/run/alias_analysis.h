// SPDX-License-Identifier: MIT
// What sampling the locomotive run at the thesis's 6 Hz does to the wheelset's lateral mode,
// against sampling faster, filtering on the FPGA and decimating: used by `flange demo`.
#pragma once

#include <string>

namespace flange::host {

struct AliasAnalysisInput {
  std::string fast_recording;  // the loco run sampled fast (its clearance_mm is the truth)
  std::string slow_output;     // flange run output of the same run sampled at the slow rate
  std::string fast_output;     // flange run output of the fast recording
  std::string slow_coeffs;     // filter.json used on the slow recording
  std::string fast_coeffs;     // filter.json used on the fast recording
  int decimation = 16;         // fast rate / slow rate
  double truth_band_hz = 1.0;  // the "slow truth": the fast truth through a zero-phase brick wall
  double skip_s = 30.0;        // start-up left out of the errors
};

struct AliasAnalysis {
  double mode_hz = 0.0;                // spectral peak of the fast truth in 3-10 Hz
  double alias_hz = 0.0;               // where that mode lands when sampled at the slow rate
  double slow_gain_at_alias_db = 0.0;  // slow filter's gain at the alias
  double fast_gain_at_mode_db = 0.0;   // fast filter's gain at the mode, before decimation
  double slow_rms_mm = 0.0;            // slow chain's filtered clearance vs the slow truth
  double fast_rms_mm = 0.0;            // fast chain, decimated, vs the slow truth
};

// Throws InputError for unreadable inputs.
AliasAnalysis analyse_aliasing(const AliasAnalysisInput& input);

}  // namespace flange::host
