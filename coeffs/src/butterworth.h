// SPDX-License-Identifier: MIT
// Butterworth low-pass design: minimal order from a spec, analog prototype, pre-warped
// bilinear transform. Follows the thesis eqs. 4.8-4.10 and scipy.signal.buttord/butter.
#pragma once

#include <optional>
#include <vector>

#include "polynomial.h"

namespace flange::coeffs {

inline constexpr int kMinOrder = 1;
inline constexpr int kMaxOrder = 32;

// A low-pass mask. Valid: all finite, fs_hz > 0, 0 < fp_hz < fa_hz < fs_hz / 2,
// 0 < ap_db < aa_db.
struct LowpassSpec {
  double fs_hz = 0.0;  // sample rate
  double fp_hz = 0.0;  // passband edge
  double fa_hz = 0.0;  // stopband edge
  double ap_db = 0.0;  // maximum passband loss
  double aa_db = 0.0;  // minimum stopband attenuation
};

// Zeros, poles and gain of a digital filter.
struct Zpk {
  std::vector<Complex> zeros;
  std::vector<Complex> poles;
  double gain = 1.0;
};

// Minimal order meeting `spec` by the pre-warped bilinear formula (thesis eq. 4.8). May exceed
// kMaxOrder; the caller checks.
int butterworth_min_order(const LowpassSpec& spec);

// 3 dB cut-off (Hz) of the order-`order` Butterworth filter whose loss at spec.fp_hz is exactly
// spec.ap_db (as buttord).
double butterworth_cutoff_hz(const LowpassSpec& spec, int order);

// Digital Butterworth low-pass: order in [1, 32], 0 < fc_hz < fs_hz / 2.
Zpk butterworth_lowpass(int order, double fc_hz, double fs_hz);

}  // namespace flange::coeffs
