// SPDX-License-Identifier: MIT
// The converter grid both parts of a diagnosis lie on, if they lie on one.
#pragma once

#include <optional>

#include "adc_grid.h"
#include "recording_series.h"

namespace flange::diagnose {

// Two parts' grids are one converter's: the same LSB (within 0.1 %), codes on one lattice
// (within 5 % of an LSB).
bool same_grid(const AdcGrid& a, const AdcGrid& b);

// The grid estimated from both parts' voltages together, when each part lies on a grid and the
// two are one converter's.
std::optional<AdcGrid> shared_grid(const RecordingSeries& calibration,
                                   const RecordingSeries& heldout);

}  // namespace flange::diagnose
