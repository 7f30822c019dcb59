// SPDX-License-Identifier: MIT
#include "welch_spectrum.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>
#include <unsupported/Eigen/FFT>

namespace flange::host {

WelchSpectrum::WelchSpectrum(std::size_t segment, double fs_hz)
    : segment_(segment), fs_hz_(fs_hz), window_(segment), sum_(segment / 2 + 1, 0.0) {
  if (segment < 16 || (segment & (segment - 1)) != 0 || !(fs_hz > 0.0)) {
    throw std::invalid_argument("WelchSpectrum: segment must be a power of two >= 16, fs > 0");
  }
  for (std::size_t n = 0; n < segment; ++n) {
    window_[n] = 0.5 - 0.5 * std::cos(2.0 * std::numbers::pi * static_cast<double>(n) /
                                      static_cast<double>(segment));
    window_power_ += window_[n] * window_[n];
  }
  buffer_.assign(segment, 0.0);
}

void WelchSpectrum::push(double value) {
  buffer_[head_] = value;  // a ring: head_ is the oldest sample once the ring is full
  head_ = (head_ + 1) % segment_;
  filled_ = std::min(filled_ + 1, segment_);
  ++since_last_;
  // A segment every half segment: 50 % overlap.
  if (filled_ == segment_ && since_last_ >= segment_ / 2) {
    take_segment();
    since_last_ = 0;
  }
}

void WelchSpectrum::take_segment() {
  double mean = 0.0;
  for (double v : buffer_) mean += v;
  mean /= static_cast<double>(segment_);
  std::vector<double> windowed(segment_);
  for (std::size_t n = 0; n < segment_; ++n) {
    windowed[n] = (buffer_[(head_ + n) % segment_] - mean) * window_[n];
  }
  Eigen::FFT<double> fft;
  std::vector<std::complex<double>> spectrum;
  fft.fwd(spectrum, windowed);
  for (std::size_t k = 0; k < sum_.size(); ++k) sum_[k] += std::norm(spectrum[k]);
  ++segments_;
}

std::vector<double> WelchSpectrum::psd() const {
  if (segments_ == 0) return {};
  std::vector<double> out(sum_.size());
  const double scale = 1.0 / (fs_hz_ * window_power_ * static_cast<double>(segments_));
  for (std::size_t k = 0; k < out.size(); ++k) {
    const bool edge = k == 0 || k + 1 == out.size();
    out[k] = sum_[k] * scale * (edge ? 1.0 : 2.0);
  }
  return out;
}

std::vector<double> WelchSpectrum::frequencies_hz() const {
  std::vector<double> f(sum_.size());
  for (std::size_t k = 0; k < f.size(); ++k) {
    f[k] = fs_hz_ * static_cast<double>(k) / static_cast<double>(segment_);
  }
  return f;
}

}  // namespace flange::host
