// SPDX-License-Identifier: MIT
// The library's formulas first; only when what they leave is above the noise, a second pass with
// the free-shape families competing too, kept when it leaves significantly less on held-out data
// or names fewer classes that leave as little. A free curve fitted early is not refitted around
// later picks, so letting it compete from the start would let it take part of an effect the
// library explains exactly (an offset curve of T takes the hysteresis of a thermal lag).
#pragma once

#include <optional>

#include "adc_grid.h"
#include "parts.h"
#include "selection.h"

namespace flange::diagnose {

// Whether the free pass replaces the library pass (criteria::kPassComparisonMargin); public for
// its test (tests/diagnose/selection_rules_test.cpp).
bool free_pass_wins(const Selection& library, const Selection& free, bool several_classes);

// The pass taken, with the white noise it re-estimated (Selection::reestimated_noise) on the
// calibration part's converter grid `cal_grid`.
Selection select_in_two_passes(const Parts& parts, const DiagnoseOptions& options,
                               const std::optional<AdcGrid>& cal_grid, const Selection& start);

}  // namespace flange::diagnose
