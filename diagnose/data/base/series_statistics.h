// SPDX-License-Identifier: MIT
// Statistics of a gap (real minus sim) series: its white-noise level, whiteness and
// residual-input correlation tests (as MATLAB's `resid` draws them), spectra and coherence,
// and change points of its mean.
#pragma once

#include <cstddef>
#include <vector>

namespace flange::diagnose {

double mean_of(const std::vector<double>& x);
double rms_of(const std::vector<double>& x);
double max_abs_of(const std::vector<double>& x);

// The part of a gap's RMS above white noise of RMS `noise`: sqrt(rms^2 - noise^2), 0 below it.
double rms_above_noise(double rms, double noise);

// Whether `curve` sums below zero over the samples whose `v` lies at or above v's median: a
// curve that lowers the upper half of the voltages, as a compression of the range's top does.
// False for no samples or sizes that differ.
bool lowers_the_upper_half(const std::vector<double>& v, const std::vector<double>& curve);

// y = intercept + slope x by least squares, with the t statistic of the slope. `fitted` is false
// (and the rest 0) for fewer than 3 points or an x that does not vary.
struct LineFit {
  bool fitted = false;
  double intercept = 0.0, slope = 0.0, slope_t = 0.0;
};
LineFit line_fit(const std::vector<double>& x, const std::vector<double>& y);

// The standard deviation of the white part of `x`: 1.4826 * MAD(differences at `lag`) / sqrt(2).
// Differencing removes what moves slowly (drifts, offsets, the effects of temperature); the
// median ignores the few large jumps of a clearance step. Lag 2 is unbiased also when
// neighbouring samples share noise (a channel interpolated between samples). Needs lag + 2
// samples.
double white_noise_std(const std::vector<double>& x, std::size_t lag = 1);

// Normalised autocorrelation of x (mean removed) at lags 0..max_lag.
std::vector<double> autocorrelation(const std::vector<double>& x, std::size_t max_lag);
// Normalised cross-correlation r_xy(k) = E[x(n+k) y(n)] at lags -max_lag..max_lag (index
// k + max_lag), means removed.
std::vector<double> cross_correlation(const std::vector<double>& x, const std::vector<double>& y,
                                      std::size_t max_lag);

// A correlation test at the 99 % level: |r| beyond 2.576 / sqrt(N) counts as outside.
struct CorrelationTest {
  std::size_t max_lag = 0;
  double bound = 0.0;
  std::size_t lags_outside = 0;  // among the lags tested (1..max_lag, or all for cross tests)
  std::size_t lags_tested = 0;
  double max_abs = 0.0;
  bool passed = true;  // no more lags outside than 1 % of the lags tested plus one allows
};
CorrelationTest whiteness_test(const std::vector<double>& residual, std::size_t max_lag);
CorrelationTest independence_test(const std::vector<double>& residual,
                                  const std::vector<double>& input, std::size_t max_lag);

struct Spectrum {
  std::vector<double> frequency_hz;
  std::vector<double> value;  // PSD (units^2/Hz) or coherence (0..1)
};
// Welch PSD with Hann segments of `segment` samples (a power of two), half overlapping.
Spectrum welch_psd(const std::vector<double>& x, double fs_hz, std::size_t segment);
// Magnitude-squared coherence of x and y from the same segments.
Spectrum coherence(const std::vector<double>& x, const std::vector<double>& y, double fs_hz,
                   std::size_t segment);
// The largest power of two <= n / 8, within [16, 256]: at least about 15 averaged segments.
std::size_t spectrum_segment(std::size_t n);

struct MeanSegment {
  std::size_t begin = 0, end = 0;  // [begin, end) sample indices
  double mean = 0.0;
};
// Binary segmentation on the mean (CUSUM split points). A split is kept when the two sides'
// means differ by more than `min_shift` and by more than 4 standard errors of `noise_std`
// white noise; segments are at least `min_length` samples; at most `max_segments`, the strongest
// splits (largest between-segment sum of squares) kept first.
std::vector<MeanSegment> mean_change_points(const std::vector<double>& x, double noise_std,
                                            double min_shift, std::size_t min_length,
                                            std::size_t max_segments);

}  // namespace flange::diagnose
