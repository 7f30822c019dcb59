// SPDX-License-Identifier: MIT
// The twin's white voltage noise the diagnosis compares with: estimated from the calibration part
// (on its converter grid, if it has one), or the twin's own.
#pragma once

#include <vector>

#include "diagnosis.h"
#include "diagnosis_detail.h"
#include "recording_series.h"

namespace flange::diagnose {

// Fills detail's adc_grid, white_noise, noise_std_v and noise_source; `cal_base_v` is the twin
// replayed on the calibration part.
void estimate_noise(const RecordingSeries& calibration, const std::vector<double>& cal_base_v,
                    const DiagnoseOptions& options, DiagnosisDetail& detail);

}  // namespace flange::diagnose
