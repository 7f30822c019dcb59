// SPDX-License-Identifier: MIT
// Spectral checks for the sim tests: the amplitude of one frequency in a sampled signal (a
// single-bin DFT at any frequency, not only on the FFT grid) and the frequency of the largest.
#pragma once

#include <cmath>
#include <complex>
#include <numbers>
#include <numeric>
#include <vector>

namespace flange::sim::testing {

// Amplitude of the tone at `frequency_hz` in `x` sampled at `fs_hz`, mean removed: 2 |X(f)| / N
// (a full-record sinusoid of amplitude A at f gives A; DC gives its value).
inline double tone_amplitude(const std::vector<double>& x, double fs_hz, double frequency_hz) {
  const double mean = std::accumulate(x.begin(), x.end(), 0.0) / static_cast<double>(x.size());
  std::complex<double> sum = 0.0;
  for (std::size_t n = 0; n < x.size(); ++n) {
    const double phase = -2.0 * std::numbers::pi * frequency_hz * static_cast<double>(n) / fs_hz;
    sum += (x[n] - (frequency_hz == 0.0 ? 0.0 : mean)) * std::polar(1.0, phase);
  }
  const double scale = frequency_hz == 0.0 ? 1.0 : 2.0;
  return scale * std::abs(sum) / static_cast<double>(x.size());
}

// The frequency in [low, high] (step apart) where tone_amplitude is largest.
inline double peak_frequency(const std::vector<double>& x, double fs_hz, double low_hz,
                             double high_hz, double step_hz) {
  double best_hz = low_hz;
  double best = -1.0;
  for (double f = low_hz; f <= high_hz + 1e-12; f += step_hz) {
    const double amplitude = tone_amplitude(x, fs_hz, f);
    if (amplitude > best) {
      best = amplitude;
      best_hz = f;
    }
  }
  return best_hz;
}

// Share of the signal's power (mean removed) inside [low, high] Hz, from its DFT on the
// natural grid k fs / N.
inline double power_share_in_band(const std::vector<double>& x, double fs_hz, double low_hz,
                                  double high_hz) {
  const std::size_t n = x.size();
  double in_band = 0.0;
  double total = 0.0;
  for (std::size_t k = 1; k <= n / 2; ++k) {
    const double f = fs_hz * static_cast<double>(k) / static_cast<double>(n);
    const double amplitude = tone_amplitude(x, fs_hz, f);
    total += amplitude * amplitude;
    if (f >= low_hz && f <= high_hz) in_band += amplitude * amplitude;
  }
  return in_band / total;
}

}  // namespace flange::sim::testing
