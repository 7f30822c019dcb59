// SPDX-License-Identifier: MIT
// The clearance and temperature ranges of the recordings an effect's parameters were fitted on
// (twin file: an effect's "fitted_over"; `flange diagnose` writes them into the twin it hands
// back). Within them the effect stands for what was measured; beyond them it continues its curves
// past any measurement. The twin plays the effect alike everywhere; a diagnosis against the twin
// reads them to tell a gap the twin was fitted to leave out from one it should have explained.
#pragma once

#include <optional>
#include <string>

namespace flange::sim {

struct FittedRanges {
  double clearance_lo_mm = 0.0, clearance_hi_mm = 0.0;
  double temperature_lo_c = 0.0, temperature_hi_c = 0.0;
  bool operator==(const FittedRanges&) const = default;

  bool contains(double clearance_mm, double temperature_c) const {
    return clearance_mm >= clearance_lo_mm && clearance_mm <= clearance_hi_mm &&
           temperature_c >= temperature_lo_c && temperature_c <= temperature_hi_c;
  }
};

// The valid ranges of their bounds: the recordings' temperature range (a type-K thermocouple as
// the host reads it) and any clearance a sensor could face.
inline constexpr double kFittedClearanceMaxMm = 1000.0;
inline constexpr double kFittedTemperatureMinC = -40.0, kFittedTemperatureMaxC = 200.0;

// "" when the ranges are well formed (finite, low <= high, within the valid ranges above), else
// one sentence naming the field and its valid range ("temperature_c: ...").
std::string fitted_ranges_problem(const FittedRanges& ranges);

// The box both ranges share, or nothing when they do not overlap.
std::optional<FittedRanges> overlap(const FittedRanges& a, const FittedRanges& b);

}  // namespace flange::sim
