// SPDX-License-Identifier: MIT
#include "butterworth.h"

#include <cmath>
#include <numbers>

namespace flange::coeffs {

namespace {

// Pre-warped analog frequency of a digital frequency normalised to Nyquist (scipy's `fs = 2`
// convention: Omega = 2 fs tan(pi w / fs) with fs = 2).
double prewarp_normalised(double normalised) {
  return std::tan(std::numbers::pi * normalised / 2.0);
}

}  // namespace

int butterworth_min_order(const LowpassSpec& spec) {
  const double passband = prewarp_normalised(2.0 * spec.fp_hz / spec.fs_hz);
  const double stopband = prewarp_normalised(2.0 * spec.fa_hz / spec.fs_hz);
  const double stop_power = std::pow(10.0, 0.1 * spec.aa_db);
  const double pass_power = std::pow(10.0, 0.1 * spec.ap_db);
  // log(lambda / epsilon) / log(Omega_a / Omega_p), with lambda^2 = 10^(aa/10) - 1 and
  // epsilon^2 = 10^(ap/10) - 1.
  const double order =
      std::log10((stop_power - 1.0) / (pass_power - 1.0)) / (2.0 * std::log10(stopband / passband));
  return static_cast<int>(std::ceil(order));
}

double butterworth_cutoff_hz(const LowpassSpec& spec, int order) {
  const double passband = prewarp_normalised(2.0 * spec.fp_hz / spec.fs_hz);
  const double pass_power = std::pow(10.0, 0.1 * spec.ap_db);
  // Place the 3 dB point so that the loss at the passband edge is exactly ap.
  const double w0 = std::pow(pass_power - 1.0, -1.0 / (2.0 * order));
  const double normalised = (2.0 / std::numbers::pi) * std::atan(w0 * passband);
  return normalised * spec.fs_hz / 2.0;
}

Zpk butterworth_lowpass(int order, double fc_hz, double fs_hz) {
  // Analog prototype poles on the unit circle's left half, in numpy's order (m = -N+1 .. N-1),
  // scaled to the pre-warped cut-off.
  const double normalised = 2.0 * fc_hz / fs_hz;
  const double warped = 4.0 * std::tan(std::numbers::pi * normalised / 2.0);
  constexpr double kBilinearTwoFs = 4.0;  // 2 fs with the normalised fs = 2
  Zpk zpk;
  Complex denominator_product(1.0, 0.0);
  for (int m = -order + 1; m < order; m += 2) {
    const Complex prototype = -std::exp(Complex(0.0, std::numbers::pi * m / (2.0 * order)));
    const Complex analog = warped * prototype;
    // Bilinear transform: z = (2 fs + s) / (2 fs - s).
    zpk.poles.push_back((kBilinearTwoFs + analog) / (kBilinearTwoFs - analog));
    denominator_product *= (kBilinearTwoFs - analog);
    zpk.zeros.emplace_back(-1.0, 0.0);  // all N analog zeros at infinity map to z = -1
  }
  zpk.gain = std::pow(warped, order) / denominator_product.real();
  // The prototype pole for m = 0 is real; make its imaginary part exactly zero.
  for (Complex& pole : zpk.poles) {
    if (std::abs(pole.imag()) <= 1e-15 * std::abs(pole)) pole.imag(0.0);
  }
  return zpk;
}

}  // namespace flange::coeffs
