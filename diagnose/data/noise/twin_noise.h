// SPDX-License-Identifier: MIT
// The twin's white voltage noise the diagnosis compares with: estimated from the calibration part
// (on its converter grid, if it has one), or the twin's own.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "adc_grid.h"
#include "diagnosis.h"
#include "recording_series.h"
#include "white_noise.h"

namespace flange::diagnose {

// The noise stage's value.
struct TwinNoise {
  double noise_std_v = 0.0;  // the twin's white voltage noise, estimated or given
  std::string noise_source;  // how it was obtained
  WhiteNoise white_noise;    // the same, with the analog part and the grid it was estimated on
  std::optional<AdcGrid> adc_grid;  // the calibration part's converter grid, if it has one
};

// `cal_base_v` is the twin replayed on the calibration part.
TwinNoise estimate_noise(const RecordingSeries& calibration, const std::vector<double>& cal_base_v,
                         const DiagnoseOptions& options);

}  // namespace flange::diagnose
