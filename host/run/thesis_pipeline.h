// SPDX-License-Identifier: MIT
// The thesis's own chain, for comparison in `flange demo`: the fixed regression of eq. 3.14 and
// the filter of eq. 4.15 exactly as printed, in double precision, direct form.
#pragma once

#include <cstdint>
#include <string>

#include "run_pipeline.h"

namespace flange::host {

struct ThesisPipelineResult {
  ErrorStats before;      // eq. 3.14 against the reference
  ErrorStats after;       // eq. 4.15 output against the reference, delay-aligned
  int delay_samples = 0;  // the printed filter's group delay at DC, rounded
  double dc_gain = 0.0;   // sum b / sum a of the printed coefficients
};

// Runs the recording (strict reading) through the thesis chain; `settle_samples` at the start
// are left out of the after-filter errors, as in flange run.
ThesisPipelineResult run_thesis_pipeline(const std::string& recording_csv,
                                         std::uint64_t settle_samples);

}  // namespace flange::host
