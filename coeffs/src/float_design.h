// SPDX-License-Identifier: MIT
// The double-precision design of a filter: what the quantised hardware approximates.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "butterworth.h"
#include "second_order_sections.h"

namespace flange::coeffs {

struct FloatDesign {
  double fs_hz = 0.0;
  int order = 0;
  double fc_hz = 0.0;               // 3 dB cut-off
  std::optional<LowpassSpec> spec;  // the mask the design must meet, when one was given
  Zpk zpk;
  std::vector<double> b;  // numerator, b[0] first (z^0)
  std::vector<double> a;  // denominator, a[0] = 1
  ScaledCascade cascade;  // second-order sections, L-infinity scaled
};

// Designs the Butterworth low-pass of the given order and cut-off: zpk, b/a and the scaled
// cascade. order in [1, 32]; 0 < fc_hz < fs_hz / 2.
FloatDesign design_butterworth(int order, double fc_hz, double fs_hz,
                               std::optional<LowpassSpec> spec);

}  // namespace flange::coeffs
