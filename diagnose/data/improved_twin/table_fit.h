// SPDX-License-Identifier: MIT
// The table (sim::EffectTable) that replays what the free shapes add to the twin's voltage: a
// surface over clearance and temperature, and, for shapes of the sensor's age, a curve of the
// age, fitted by least squares to what the shapes add at every sample of both parts. The shapes
// are known functions, not data: the fit only tabulates them, on a grid fine enough that it
// reproduces them to a small part of the noise (the misfit says how far).
#pragma once

#include <vector>

#include "effect_table.h"

namespace flange::diagnose {

// One part's samples: where each lies and what the shapes add there.
struct TabulatedPart {
  const std::vector<double>& clearance_mm;
  const std::vector<double>& temperature_c;
  std::vector<double> age_days;  // the sensor's age (empty unless the table has an age curve)
  const std::vector<double>& added_v;
};

struct TableFit {
  sim::EffectTable table;
  std::vector<double> misfit_rms_v;  // per part: RMS of the table less what the shapes add, V
};

// The table over the parts' ranges: knots at most kClearanceKnotSpacingMm and
// kTemperatureKnotSpacingC apart, an age curve when `with_age` (every part then gives its ages).
TableFit fit_effect_table(const std::vector<TabulatedPart>& parts, bool with_age);

// Knot spacing: a ripple of 2 mm in clearance gets ten knots to its period; a curve of
// temperature bends at most every 4 degC in the free shapes (7 knots over a 20-80 degC session).
inline constexpr double kClearanceKnotSpacingMm = 0.25;
inline constexpr double kTemperatureKnotSpacingC = 2.5;
// An age curve's knots per part, over each part's own ages (the sessions may lie days apart).
inline constexpr int kAgeKnotsPerPart = 17;

}  // namespace flange::diagnose
