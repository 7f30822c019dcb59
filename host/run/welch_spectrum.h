// SPDX-License-Identifier: MIT
// A power spectral density estimated while samples stream past (Welch: Hann-windowed
// segments, half overlapping, averaged), so a report can show spectra of any length of run
// in constant memory.
#pragma once

#include <cstddef>
#include <vector>

namespace flange::host {

class WelchSpectrum {
 public:
  // segment: samples per FFT, a power of two >= 16. fs_hz > 0.
  WelchSpectrum(std::size_t segment, double fs_hz);

  void push(double value);
  std::size_t segments() const { return segments_; }
  // One-sided PSD (units^2/Hz) at bin frequencies k fs / segment, k = 0..segment/2. Empty when
  // no segment was complete.
  std::vector<double> psd() const;
  std::vector<double> frequencies_hz() const;

 private:
  void take_segment();

  std::size_t segment_;
  double fs_hz_;
  std::vector<double> window_;
  std::vector<double> buffer_;  // ring of the last `segment_` samples
  std::size_t head_ = 0;        // next slot to write (the oldest sample when full)
  std::size_t filled_ = 0;
  std::size_t since_last_ = 0;  // samples pushed since the last segment was taken
  std::vector<double> sum_;     // accumulated |X_k|^2
  std::size_t segments_ = 0;
  double window_power_ = 0.0;
};

}  // namespace flange::host
