// SPDX-License-Identifier: MIT
// The white noise the diagnosis compares every gap with, estimated from the data. Without a
// converter grid (or with one much finer than the noise) it is the median-based estimate of
// series_statistics.h at lag 2. On a coarse grid (an LSB above an eighth of that estimate) the
// median collapses or sits on the lattice of code steps, so the analog noise comes from the
// grid-aware fit of quantised_noise.h, and the noise of the gap against the unquantised twin
// adds the quantisation error: sqrt(analog^2 + LSB^2 / 12).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "adc_grid.h"

namespace flange::diagnose {

struct WhiteNoise {
  double analog_std_v = 0.0;     // before the converter
  double effective_std_v = 0.0;  // of the recording less the unquantised twin (>= analog)
  std::optional<AdcGrid> grid;   // the recording's converter grid, when it has one
  bool grid_aware = false;       // the analog noise came from the grid-aware fit
  std::string source;            // how it was obtained, one sentence

  // A sample of the noisy twin: `twin_v` plus the analog noise scaled from `standard_normal`,
  // put on the grid when there is one.
  double noisy(double twin_v, double standard_normal) const;
  // What the recording less the twin quantised on the grid leaves with this noise alone (the
  // effective noise when there is no grid).
  double quantised_null_rms() const;
};

// From the recorded voltage and the twin's noise-free voltage for the same samples (at least
// 20 of each).
WhiteNoise estimate_white_noise(const std::vector<double>& recorded_v,
                                const std::vector<double>& twin_v,
                                const std::optional<AdcGrid>& grid);

// The twin's own noise level as the analog noise, with the grid's quantisation added.
WhiteNoise given_white_noise(double analog_std_v, const std::optional<AdcGrid>& grid);

}  // namespace flange::diagnose
