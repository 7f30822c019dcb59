// SPDX-License-Identifier: MIT
// The signatures stage's value: the noise-type classes recognised after the picks (the converter
// from the recorded codes, mount motion from how the gap's variance follows the sensitivity), and
// every finding in the order the report lists them.
#pragma once

#include <optional>
#include <vector>

#include "adc_grid.h"
#include "diagnosis.h"
#include "selection.h"

namespace flange::diagnose {

struct Signatures {
  std::optional<EffectFinding> quantisation;
  std::optional<AdcGrid> quantised_on;  // the converter grid, once recognised
  bool quantisation_as_noise = false;   // its codes not reproduced: taken as noise
  std::optional<EffectFinding> vibration;
};

// Every finding in the order the report lists them: the picks in the order the rounds took them,
// the converter before the first pick that takes less of the held-out gap's RMS than its rounding
// puts in it (LSB / sqrt(12)), mount motion last.
std::vector<EffectFinding> findings_of(const Selection& selection, const Signatures& signatures);

}  // namespace flange::diagnose
