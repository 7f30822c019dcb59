// SPDX-License-Identifier: MIT
#include "series_statistics.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <optional>
#include <queue>
#include <stdexcept>
#include <unsupported/Eigen/FFT>

#include "series_arithmetic.h"
#include "welch_spectrum.h"

namespace flange::diagnose {

using host::WelchSpectrum;

bool lowers_the_upper_half(const std::vector<double>& v, const std::vector<double>& curve) {
  if (v.empty() || v.size() != curve.size()) return false;
  const double middle = median_of(v);
  double upper_sum = 0.0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (v[i] >= middle) upper_sum += curve[i];
  }
  return upper_sum < 0.0;
}

LineFit line_fit(const std::vector<double>& x, const std::vector<double>& y) {
  LineFit fit;
  const std::size_t n = y.size();
  if (n < 3 || x.size() != n) return fit;
  Eigen::MatrixXd design(n, 2);
  Eigen::VectorXd target(n);
  for (std::size_t i = 0; i < n; ++i) {
    design(static_cast<Eigen::Index>(i), 0) = 1.0;
    design(static_cast<Eigen::Index>(i), 1) = x[i];
    target(static_cast<Eigen::Index>(i)) = y[i];
  }
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(design);
  if (qr.rank() < 2) return fit;
  const Eigen::Vector2d beta = qr.solve(target);
  const double variance = (target - design * beta).squaredNorm() / static_cast<double>(n - 2);
  const Eigen::Matrix2d covariance = variance * (design.transpose() * design).inverse();
  fit.fitted = true;
  fit.intercept = beta(0);
  fit.slope = beta(1);
  fit.slope_t = beta(1) / std::sqrt(covariance(1, 1));
  return fit;
}

double mean_of(const std::vector<double>& x) {
  double sum = 0.0;
  for (double v : x) sum += v;
  return x.empty() ? 0.0 : sum / static_cast<double>(x.size());
}

double rms_of(const std::vector<double>& x) {
  double sum = 0.0;
  for (double v : x) sum += v * v;
  return x.empty() ? 0.0 : std::sqrt(sum / static_cast<double>(x.size()));
}

double max_abs_of(const std::vector<double>& x) {
  double m = 0.0;
  for (double v : x) m = std::max(m, std::abs(v));
  return m;
}

double rms_above_noise(double rms, double noise) {
  return std::sqrt(std::max(0.0, rms * rms - noise * noise));
}

double white_noise_std(const std::vector<double>& x, std::size_t lag) {
  if (lag < 1 || x.size() < lag + 2) {
    throw std::invalid_argument("white_noise_std: fewer than lag + 2 samples");
  }
  std::vector<double> d(x.size() - lag);
  for (std::size_t i = 0; i + lag < x.size(); ++i) d[i] = x[i + lag] - x[i];
  const auto median = [](std::vector<double> v) {
    const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
    std::nth_element(v.begin(), mid, v.end());
    return *mid;
  };
  const double center = median(d);
  for (double& v : d) v = std::abs(v - center);
  return 1.4826 * median(d) / std::sqrt(2.0);
}

namespace {

std::vector<double> centered(const std::vector<double>& x) {
  const double m = mean_of(x);
  std::vector<double> c(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) c[i] = x[i] - m;
  return c;
}

double correlation_at(const std::vector<double>& x, const std::vector<double>& y, long lag,
                      double norm) {
  double sum = 0.0;
  const long n = static_cast<long>(x.size());
  for (long i = std::max(0L, -lag); i < n && i + lag < n; ++i) {
    sum += x[static_cast<std::size_t>(i + lag)] * y[static_cast<std::size_t>(i)];
  }
  return norm > 0.0 ? sum / norm : 0.0;
}

CorrelationTest count_outside(const std::vector<double>& r, std::size_t first, std::size_t n,
                              std::size_t max_lag) {
  CorrelationTest test;
  test.max_lag = max_lag;
  test.bound = 2.576 / std::sqrt(static_cast<double>(n));
  for (std::size_t k = first; k < r.size(); ++k) {
    ++test.lags_tested;
    test.max_abs = std::max(test.max_abs, std::abs(r[k]));
    if (std::abs(r[k]) > test.bound) ++test.lags_outside;
  }
  test.passed =
      static_cast<double>(test.lags_outside) <= 1.0 + 0.01 * static_cast<double>(test.lags_tested);
  return test;
}

}  // namespace

std::vector<double> autocorrelation(const std::vector<double>& x, std::size_t max_lag) {
  const std::vector<double> c = centered(x);
  double norm = 0.0;
  for (double v : c) norm += v * v;
  std::vector<double> r(max_lag + 1);
  for (std::size_t k = 0; k <= max_lag; ++k)
    r[k] = correlation_at(c, c, static_cast<long>(k), norm);
  return r;
}

std::vector<double> cross_correlation(const std::vector<double>& x, const std::vector<double>& y,
                                      std::size_t max_lag) {
  const std::vector<double> cx = centered(x), cy = centered(y);
  double sx = 0.0, sy = 0.0;
  for (double v : cx) sx += v * v;
  for (double v : cy) sy += v * v;
  const double norm = std::sqrt(sx * sy);
  std::vector<double> r(2 * max_lag + 1);
  const long m = static_cast<long>(max_lag);
  for (long k = -m; k <= m; ++k)
    r[static_cast<std::size_t>(k + m)] = correlation_at(cx, cy, k, norm);
  return r;
}

CorrelationTest whiteness_test(const std::vector<double>& residual, std::size_t max_lag) {
  return count_outside(autocorrelation(residual, max_lag), 1, residual.size(), max_lag);
}

CorrelationTest independence_test(const std::vector<double>& residual,
                                  const std::vector<double>& input, std::size_t max_lag) {
  return count_outside(cross_correlation(residual, input, max_lag), 0, residual.size(), max_lag);
}

std::size_t spectrum_segment(std::size_t n) {
  std::size_t segment = 16;
  while (segment * 2 <= n / 8 && segment < 256) segment *= 2;
  return segment;
}

Spectrum welch_psd(const std::vector<double>& x, double fs_hz, std::size_t segment) {
  WelchSpectrum welch(segment, fs_hz);
  for (double v : x) welch.push(v);
  return {welch.frequencies_hz(), welch.psd()};
}

Spectrum coherence(const std::vector<double>& x, const std::vector<double>& y, double fs_hz,
                   std::size_t segment) {
  const std::size_t bins = segment / 2 + 1;
  std::vector<double> sxx(bins, 0.0), syy(bins, 0.0);
  std::vector<std::complex<double>> sxy(bins, 0.0);
  std::vector<double> window(segment);
  for (std::size_t n = 0; n < segment; ++n) {
    window[n] = 0.5 - 0.5 * std::cos(2.0 * std::numbers::pi * static_cast<double>(n) /
                                     static_cast<double>(segment));
  }
  Eigen::FFT<double> fft;
  std::vector<double> bx(segment), by(segment);
  std::vector<std::complex<double>> fx, fy;
  for (std::size_t start = 0; start + segment <= x.size(); start += segment / 2) {
    double mx = 0.0, my = 0.0;
    for (std::size_t n = 0; n < segment; ++n) {
      mx += x[start + n];
      my += y[start + n];
    }
    mx /= static_cast<double>(segment);
    my /= static_cast<double>(segment);
    for (std::size_t n = 0; n < segment; ++n) {
      bx[n] = (x[start + n] - mx) * window[n];
      by[n] = (y[start + n] - my) * window[n];
    }
    fft.fwd(fx, bx);
    fft.fwd(fy, by);
    for (std::size_t k = 0; k < bins; ++k) {
      sxx[k] += std::norm(fx[k]);
      syy[k] += std::norm(fy[k]);
      sxy[k] += fx[k] * std::conj(fy[k]);
    }
  }
  Spectrum result;
  for (std::size_t k = 0; k < bins; ++k) {
    result.frequency_hz.push_back(fs_hz * static_cast<double>(k) / static_cast<double>(segment));
    const double denominator = sxx[k] * syy[k];
    result.value.push_back(denominator > 0.0 ? std::norm(sxy[k]) / denominator : 0.0);
  }
  return result;
}

namespace {

// The best split of [begin, end) by the mean, when it is kept (see mean_change_points), with its
// strength: the between-segment sum of squares it explains.
struct Split {
  std::size_t begin = 0, end = 0, at = 0;
  double score = 0.0;
  bool operator<(const Split& other) const { return score < other.score; }
};

std::optional<Split> best_split(const std::vector<double>& x, std::size_t begin, std::size_t end,
                                double noise_std, double min_shift, std::size_t min_length) {
  if (end - begin < 2 * min_length) return std::nullopt;
  double total = 0.0;
  for (std::size_t i = begin; i < end; ++i) total += x[i];
  const double n = static_cast<double>(end - begin);
  // The split maximising the between-segment sum of squares (the CUSUM's extremum).
  double best_score = -1.0, left_sum = 0.0, best_left_mean = 0.0, best_right_mean = 0.0;
  std::size_t best = 0;
  for (std::size_t i = begin; i < end - min_length; ++i) {
    left_sum += x[i];
    const double nl = static_cast<double>(i + 1 - begin);
    if (i + 1 - begin < min_length) continue;
    const double nr = n - nl;
    const double ml = left_sum / nl, mr = (total - left_sum) / nr;
    const double score = nl * nr / n * (ml - mr) * (ml - mr);
    if (score > best_score) {
      best_score = score;
      best = i + 1;
      best_left_mean = ml;
      best_right_mean = mr;
    }
  }
  if (best == 0) return std::nullopt;
  const double nl = static_cast<double>(best - begin), nr = n - nl;
  const double shift = std::abs(best_left_mean - best_right_mean);
  const double standard_error = noise_std * std::sqrt(1.0 / nl + 1.0 / nr);
  if (shift <= min_shift || shift <= 4.0 * standard_error) return std::nullopt;
  return Split{begin, end, best, best_score};
}

}  // namespace

std::vector<MeanSegment> mean_change_points(const std::vector<double>& x, double noise_std,
                                            double min_shift, std::size_t min_length,
                                            std::size_t max_segments) {
  min_length = std::max<std::size_t>(min_length, 2);
  // Strongest split first: each taken split offers its two sides' own best splits, so a cap keeps
  // the strongest shifts wherever they lie (a side's split is never taken before its parent).
  std::priority_queue<Split> offered;
  const auto offer = [&](std::size_t begin, std::size_t end) {
    if (auto s = best_split(x, begin, end, noise_std, min_shift, min_length)) offered.push(*s);
  };
  offer(0, x.size());
  std::vector<std::size_t> cuts;
  while (!offered.empty() && cuts.size() + 1 < max_segments) {
    const Split s = offered.top();
    offered.pop();
    cuts.push_back(s.at);
    offer(s.begin, s.at);
    offer(s.at, s.end);
  }
  std::sort(cuts.begin(), cuts.end());
  std::vector<MeanSegment> segments;
  std::size_t begin = 0;
  cuts.push_back(x.size());
  for (std::size_t cut : cuts) {
    double sum = 0.0;
    for (std::size_t i = begin; i < cut; ++i) sum += x[i];
    segments.push_back({begin, cut, cut > begin ? sum / static_cast<double>(cut - begin) : 0.0});
    begin = cut;
  }
  return segments;
}

}  // namespace flange::diagnose
