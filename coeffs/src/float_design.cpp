// SPDX-License-Identifier: MIT
#include "float_design.h"

#include <utility>

namespace flange::coeffs {

FloatDesign design_butterworth(int order, double fc_hz, double fs_hz,
                               std::optional<LowpassSpec> spec) {
  FloatDesign design;
  design.fs_hz = fs_hz;
  design.order = order;
  design.fc_hz = fc_hz;
  design.spec = spec;
  design.zpk = butterworth_lowpass(order, fc_hz, fs_hz);
  design.b = poly_from_roots(design.zpk.zeros);
  for (double& coefficient : design.b) coefficient *= design.zpk.gain;
  design.a = poly_from_roots(design.zpk.poles);
  design.cascade = scale_cascade_linf(pair_sections_nearest(design.zpk), design.zpk.gain);
  return design;
}

}  // namespace flange::coeffs
