// SPDX-License-Identifier: MIT
// The residual tests of series_statistics.h (white_noise_std, autocorrelation, cross_correlation,
// whiteness_test, independence_test, welch_psd, coherence, spectrum_segment,
// mean_change_points), each on a small synthetic series whose answer is known in advance.
//
// The noise comes from sim::GaussianSource, whose numbers are the same on every standard
// library (std::normal_distribution's are not), so a count of false alarms over fixed seeds is
// the same count everywhere. The statistical bounds are set from the theory quoted beside each
// one, with a margin of 3 to 5 standard deviations, not from the counts these seeds happen to
// give: the checks are meant to fail when the estimator is wrong, not when the seeds change.
#include "series_statistics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "gaussian_source.h"

namespace flange::diagnose {
namespace {

std::vector<double> white_noise(std::uint64_t seed, std::size_t n, double sigma) {
  sim::GaussianSource source(seed);
  std::vector<double> x(n);
  for (double& v : x) v = sigma * source.standard_normal();
  return x;
}

// x(n) = phi x(n-1) + e(n), started from its stationary distribution.
std::vector<double> ar1(std::uint64_t seed, std::size_t n, double phi) {
  sim::GaussianSource source(seed);
  std::vector<double> x(n);
  double previous = source.standard_normal() / std::sqrt(1.0 - phi * phi);
  for (double& v : x) v = previous = phi * previous + source.standard_normal();
  return x;
}

std::size_t argmax_abs(const std::vector<double>& x) {
  return static_cast<std::size_t>(
      std::max_element(x.begin(), x.end(),
                       [](double a, double b) { return std::abs(a) < std::abs(b); }) -
      x.begin());
}

// The 99 % two-sided normal quantile, the bound of both correlation tests.
constexpr double kZ99 = 2.576;

// ---- white_noise_std ---------------------------------------------------------------------------

TEST(ResidualTests, WhiteNoiseStdRecoversSigmaUnderADriftAndAFewLargeJumps) {
  constexpr std::size_t kN = 10000;
  constexpr double kSigma = 0.2;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    std::vector<double> x = white_noise(seed, kN, kSigma);
    double level = 0.0;
    for (std::size_t i = 0; i < kN; ++i) {
      // A slow drift of +-25 sigma: it moves at most 5 * 2 pi / 10000 = 0.003 (1.6 % of sigma)
      // per sample, so it barely touches the differences.
      x[i] += 5.0 * std::sin(2.0 * std::numbers::pi * static_cast<double>(i) / kN);
      // Five clearance-like jumps of 15 sigma: five outliers among 9999 differences move the
      // median by about 5/9999 of a quantile, nothing.
      if (i % 2000 == 1000) level += 3.0;
      x[i] += level;
    }
    // The MAD's relative standard error on n Gaussian samples is 1.17 / sqrt(n) (its
    // efficiency is 37 %): 1.2 % on 9999 differences. They are MA(1), not independent; even
    // doubling the variance for that makes 1.7 %, and 7 % is 4 of those.
    EXPECT_NEAR(white_noise_std(x, 1) / kSigma, 1.0, 0.07) << "seed " << seed;
    EXPECT_NEAR(white_noise_std(x, 2) / kSigma, 1.0, 0.07) << "seed " << seed;
    // What the estimator is for: the plain standard deviation is dominated by the drift and
    // the jumps, tens of sigma.
    double sum_sq = 0.0;
    const double m = mean_of(x);
    for (double v : x) sum_sq += (v - m) * (v - m);
    EXPECT_GT(std::sqrt(sum_sq / kN), 10.0 * kSigma);
  }
}

TEST(ResidualTests, WhiteNoiseStdAtLagTwoIsUnbiasedWhenNeighboursShareNoise) {
  // A channel interpolated half way between samples: x(n) = (e(n) + e(n+1)) / 2, whose noise
  // has standard deviation sigma / sqrt(2). Its lag-2 differences involve four distinct e's
  // (variance sigma^2 = 2 var(x)): unbiased. Its lag-1 differences (e(n+2) - e(n)) / 2 have
  // variance sigma^2 / 2 = var(x), half of what white noise gives, so lag 1 reads sigma / 2,
  // low by sqrt(2).
  constexpr std::size_t kN = 20000;
  const std::vector<double> e = white_noise(7, kN + 1, 1.0);
  std::vector<double> x(kN);
  for (std::size_t i = 0; i < kN; ++i) x[i] = 0.5 * (e[i] + e[i + 1]);
  // Relative standard error about 1.17 * sqrt(2 / 20000) = 1.2 % (see above); 5 % is 4 of them.
  EXPECT_NEAR(white_noise_std(x, 2), std::numbers::sqrt2 / 2.0, 0.05 * std::numbers::sqrt2 / 2);
  EXPECT_NEAR(white_noise_std(x, 1), 0.5, 0.05 * 0.5);
}

TEST(ResidualTests, WhiteNoiseStdNeedsLagPlusTwoSamples) {
  EXPECT_THROW(white_noise_std({1.0, 2.0}, 1), std::invalid_argument);
  EXPECT_THROW(white_noise_std({1.0, 2.0, 3.0}, 2), std::invalid_argument);
  EXPECT_THROW(white_noise_std({1.0, 2.0, 3.0}, 0), std::invalid_argument);
  EXPECT_NO_THROW(white_noise_std({1.0, 2.0, 3.0}, 1));
  EXPECT_NO_THROW(white_noise_std({1.0, 2.0, 3.0, 4.0}, 2));
}

// ---- autocorrelation and cross_correlation ------------------------------------------------------

TEST(ResidualTests, AutocorrelationOfAnAlternatingSeriesIsKnownExactly) {
  // +1, -1, +1, ... of even length N has mean 0 and sum of squares N; the sum over the N - k
  // overlapping products is (-1)^k (N - k): r(k) = (-1)^k (N - k) / N.
  constexpr std::size_t kN = 100;
  std::vector<double> x(kN);
  for (std::size_t i = 0; i < kN; ++i) x[i] = i % 2 == 0 ? 1.0 : -1.0;
  const std::vector<double> r = autocorrelation(x, 10);
  ASSERT_EQ(r.size(), 11u);
  for (std::size_t k = 0; k <= 10; ++k) {
    const double expected = (k % 2 == 0 ? 1.0 : -1.0) * static_cast<double>(kN - k) / kN;
    EXPECT_NEAR(r[k], expected, 1e-12) << "lag " << k;
  }
}

TEST(ResidualTests, AutocorrelationOfWhiteNoiseIsOneAtLagZeroAndSmallElsewhere) {
  constexpr std::size_t kN = 4000;
  // An offset must not matter: the mean is removed.
  std::vector<double> x = white_noise(11, kN, 3.0);
  for (double& v : x) v += 100.0;
  const std::vector<double> r = autocorrelation(x, 20);
  ASSERT_EQ(r.size(), 21u);
  EXPECT_NEAR(r[0], 1.0, 1e-12);
  // r(k), k >= 1, is about N(0, 1/N): 5 / sqrt(N) is 5 standard deviations.
  for (std::size_t k = 1; k <= 20; ++k) {
    EXPECT_LT(std::abs(r[k]), 5.0 / std::sqrt(static_cast<double>(kN))) << "lag " << k;
  }
}

TEST(ResidualTests, AutocorrelationOfAnAr1IsPhiToTheLag) {
  constexpr std::size_t kN = 20000;
  constexpr double kPhi = 0.5;
  const std::vector<double> r = autocorrelation(ar1(12, kN, kPhi), 5);
  // Bartlett: the standard error of r(k) is at most sqrt((1 + phi^2) / (1 - phi^2) / N)
  // = 0.009 here; 0.04 is over 4 of them.
  for (std::size_t k = 0; k <= 5; ++k) {
    EXPECT_NEAR(r[k], std::pow(kPhi, static_cast<double>(k)), 0.04) << "lag " << k;
  }
}

TEST(ResidualTests, CrossCorrelationPeaksAtTheLagByWhichXFollowsY) {
  // x(n) = y(n - 3): r_xy(k) = E[x(n+k) y(n)] = E[y(n+k-3) y(n)] is 1 at k = +3 (index
  // k + max_lag) and about N(0, 1/N) elsewhere.
  constexpr std::size_t kN = 2000, kMaxLag = 10, kDelay = 3;
  const std::vector<double> y = white_noise(21, kN, 1.0);
  std::vector<double> x = white_noise(22, kN, 1.0);  // x(0..2): noise of its own
  for (std::size_t i = kDelay; i < kN; ++i) x[i] = y[i - kDelay];
  const std::vector<double> r = cross_correlation(x, y, kMaxLag);
  ASSERT_EQ(r.size(), 2 * kMaxLag + 1);
  EXPECT_EQ(argmax_abs(r), kMaxLag + kDelay);
  // (N - 3) / N of the shared energy overlaps: 0.9985, less sampling noise of order 1/N.
  EXPECT_GT(r[kMaxLag + kDelay], 0.99);
  for (std::size_t i = 0; i < r.size(); ++i) {
    if (i != kMaxLag + kDelay) {
      EXPECT_LT(std::abs(r[i]), 5.0 / std::sqrt(static_cast<double>(kN))) << "index " << i;
    }
  }
  // Swapping x and y mirrors the lags: r_yx(k) = r_xy(-k), term by term.
  const std::vector<double> mirrored = cross_correlation(y, x, kMaxLag);
  for (std::size_t i = 0; i < r.size(); ++i) {
    EXPECT_NEAR(mirrored[2 * kMaxLag - i], r[i], 1e-12) << "index " << i;
  }
  // With itself, it is the autocorrelation on both sides of lag 0.
  const std::vector<double> rxx = cross_correlation(y, y, kMaxLag);
  const std::vector<double> ry = autocorrelation(y, kMaxLag);
  for (std::size_t k = 0; k <= kMaxLag; ++k) {
    EXPECT_NEAR(rxx[kMaxLag + k], ry[k], 1e-12) << "lag " << k;
    EXPECT_NEAR(rxx[kMaxLag - k], ry[k], 1e-12) << "lag -" << k;
  }
}

// ---- whiteness_test ----------------------------------------------------------------------------

TEST(ResidualTests, WhitenessTestFalseAlarmsOnWhiteNoiseAtItsStatedLevel) {
  constexpr std::size_t kN = 1000, kMaxLag = 20, kSeeds = 200;
  std::size_t lags_outside = 0, failed = 0;
  for (std::uint64_t seed = 0; seed < kSeeds; ++seed) {
    const CorrelationTest t = whiteness_test(white_noise(1000 + seed, kN, 1.0), kMaxLag);
    ASSERT_EQ(t.max_lag, kMaxLag);
    ASSERT_EQ(t.lags_tested, kMaxLag);  // lags 1..max_lag
    ASSERT_NEAR(t.bound, kZ99 / std::sqrt(static_cast<double>(kN)), 1e-15);
    // The stated rule: no more lags outside than 1 + 1 % of the lags tested.
    ASSERT_EQ(t.passed, static_cast<double>(t.lags_outside) <= 1.0 + 0.01 * kMaxLag);
    lags_outside += t.lags_outside;
    if (!t.passed) ++failed;
  }
  // Per lag, r(k) of white noise is close to N(0, 1/N) and nearly independent of the other
  // lags (Bartlett), so each lag falls outside 2.576 / sqrt(N) with probability about 1 %:
  // over 200 * 20 = 4000 lags, 40 expected, binomial standard deviation 6.3. The window
  // 40 +- 22 (3.5 of them) fails a per-lag rate outside 0.45..1.55 %, such as the 0.1 % of a
  // 3.29 / sqrt(N) bound or the 2 % of a 2.32 / sqrt(N) one.
  const double lags = static_cast<double>(kSeeds * kMaxLag);
  EXPECT_NEAR(static_cast<double>(lags_outside), 0.01 * lags, 3.5 * std::sqrt(lags * 0.01 * 0.99));
  // The test as a whole fails when 2 or more of the 20 lags are outside:
  // P = 1 - 0.99^20 - 20 * 0.01 * 0.99^19 = 1.7 %, so 3.4 of 200 series expected (standard
  // deviation 1.8); 10 is over 3.5 standard deviations above.
  EXPECT_LE(failed, 10u);
}

TEST(ResidualTests, WhitenessTestRejectsAnAr1WithPhiOneHalf) {
  // r(k) = 0.5^k: 0.5 and 0.25 at lags 1 and 2 against a bound of 2.576 / sqrt(1000) = 0.081,
  // with standard errors of at most sqrt((1 + phi^2) / (1 - phi^2) / N) = 0.041: both lags
  // outside, more than the one lag the rule allows.
  constexpr std::size_t kN = 1000, kMaxLag = 20;
  for (std::uint64_t seed = 0; seed < 20; ++seed) {
    const CorrelationTest t = whiteness_test(ar1(2000 + seed, kN, 0.5), kMaxLag);
    EXPECT_FALSE(t.passed) << "seed " << seed;
    EXPECT_GE(t.lags_outside, 2u) << "seed " << seed;
    // max |r| is r(1) = 0.5, standard error sqrt((1 - phi^2) / N) = 0.027; 0.12 is over 4.
    EXPECT_NEAR(t.max_abs, 0.5, 0.12) << "seed " << seed;
  }
}

// ---- independence_test -------------------------------------------------------------------------

TEST(ResidualTests, IndependenceTestFalseAlarmsOnIndependentSeriesAtItsStatedLevel) {
  constexpr std::size_t kN = 1000, kMaxLag = 10, kSeeds = 200;
  std::size_t lags_outside = 0, failed = 0;
  for (std::uint64_t seed = 0; seed < kSeeds; ++seed) {
    const CorrelationTest t = independence_test(white_noise(3000 + seed, kN, 1.0),
                                                white_noise(4000 + seed, kN, 5.0), kMaxLag);
    ASSERT_EQ(t.lags_tested, 2 * kMaxLag + 1);  // lags -max_lag..max_lag
    ASSERT_NEAR(t.bound, kZ99 / std::sqrt(static_cast<double>(kN)), 1e-15);
    ASSERT_EQ(t.passed, static_cast<double>(t.lags_outside) <=
                            1.0 + 0.01 * static_cast<double>(2 * kMaxLag + 1));
    lags_outside += t.lags_outside;
    if (!t.passed) ++failed;
  }
  // As for the whiteness test: about 1 % of 200 * 21 = 4200 lags, 42 expected, binomial
  // standard deviation 6.4; +-3.5 of them.
  const double lags = static_cast<double>(kSeeds * (2 * kMaxLag + 1));
  EXPECT_NEAR(static_cast<double>(lags_outside), 0.01 * lags, 3.5 * std::sqrt(lags * 0.01 * 0.99));
  // A failure needs 2 of 21 lags outside: P = 1.85 %, 3.7 of 200 expected (standard
  // deviation 1.9); 10 is over 3 standard deviations above.
  EXPECT_LE(failed, 10u);
}

TEST(ResidualTests, IndependenceTestDetectsAResidualThatFollowsTheInputAtALag) {
  // residual(n) = 0.3 (u(n-3) + u(n-4) + u(n-5)) + w(n): the cross-correlation r(k) =
  // E[residual(n+k) u(n)] is 0.3 / sqrt(1 + 3 * 0.09) = 0.27 at k = 3, 4, 5 (standard error
  // 1 / sqrt(N) = 0.022) against a bound of 2.576 / sqrt(2000) = 0.058: three lags outside of
  // 21, more than the 1.21 the rule allows.
  constexpr std::size_t kN = 2000, kMaxLag = 10;
  for (std::uint64_t seed = 0; seed < 10; ++seed) {
    const std::vector<double> u = white_noise(5000 + seed, kN, 1.0);
    std::vector<double> residual = white_noise(6000 + seed, kN, 1.0);
    for (std::size_t i = 5; i < kN; ++i) residual[i] += 0.3 * (u[i - 3] + u[i - 4] + u[i - 5]);
    const CorrelationTest t = independence_test(residual, u, kMaxLag);
    EXPECT_FALSE(t.passed) << "seed " << seed;
    EXPECT_GE(t.lags_outside, 3u) << "seed " << seed;
    EXPECT_NEAR(t.max_abs, 0.27, 0.1) << "seed " << seed;
    // The lags outside are the right ones, on the positive side: the input leads.
    const std::vector<double> r = cross_correlation(residual, u, kMaxLag);
    for (std::size_t k = 3; k <= 5; ++k) {
      EXPECT_GT(r[kMaxLag + k], t.bound) << "seed " << seed << " lag " << k;
      EXPECT_LT(std::abs(r[kMaxLag - k]), t.bound) << "seed " << seed << " lag -" << k;
    }
  }
}

TEST(ResidualTests, IndependenceTestAllowsOneLagOutsideHoweverFarOutside) {
  // The stated rule lets one lag (plus 1 % of the lags tested) be outside: a residual that
  // copies a white input at one single lag has one lag far outside, and passes. (A real input
  // such as a temperature is smooth, so a real dependence spreads over many lags and fails, as
  // in the test above.)
  constexpr std::size_t kN = 2000, kMaxLag = 10;
  const std::vector<double> u = white_noise(7000, kN, 1.0);
  std::vector<double> residual = white_noise(7001, kN, 1.0);
  for (std::size_t i = 4; i < kN; ++i) residual[i] += u[i - 4];
  const CorrelationTest t = independence_test(residual, u, kMaxLag);
  // r(4) = 1 / sqrt(2) = 0.71.
  EXPECT_NEAR(t.max_abs, std::numbers::sqrt2 / 2.0, 0.1);
  EXPECT_EQ(t.lags_outside, 1u);
  EXPECT_TRUE(t.passed);
}

// ---- welch_psd, coherence, spectrum_segment ----------------------------------------------------

TEST(ResidualTests, WelchPsdOfASinusoidPeaksAtItsBinAndIntegratesToItsVariance) {
  constexpr double kFs = 1000.0, kAmplitude = 2.0;
  constexpr std::size_t kSegment = 256, kN = 8192;
  // On a bin (40 fs / 256) and between bins (40.3 fs / 256: Hann leakage spreads it, but the
  // sum over all bins is Parseval's and keeps all the power).
  for (const double bin : {40.0, 40.3}) {
    const double f0 = bin * kFs / kSegment;
    std::vector<double> x(kN);
    for (std::size_t i = 0; i < kN; ++i) {
      x[i] = 1.5 + kAmplitude *
                       std::sin(2.0 * std::numbers::pi * f0 * static_cast<double>(i) / kFs + 0.3);
    }
    const Spectrum psd = welch_psd(x, kFs, kSegment);
    ASSERT_EQ(psd.value.size(), kSegment / 2 + 1);
    ASSERT_EQ(psd.frequency_hz.size(), kSegment / 2 + 1);
    for (std::size_t k = 0; k < psd.frequency_hz.size(); ++k) {
      EXPECT_DOUBLE_EQ(psd.frequency_hz[k], kFs * static_cast<double>(k) / kSegment);
    }
    EXPECT_EQ(argmax_abs(psd.value), 40u) << "bin " << bin;
    double power = 0.0;
    for (double p : psd.value) power += p * (kFs / kSegment);
    // The variance A^2 / 2 = 2 (the offset is removed). Between bins, removing each segment's
    // mean takes out at most (A / (pi 40.3))^2 / (A^2 / 2), 0.01 %; the 2 omega term of the
    // windowed sin^2 is 80 bins away from 0, where the Hann^2 spectrum is nil. 2 % is margin.
    EXPECT_NEAR(power, kAmplitude * kAmplitude / 2.0, 0.02 * kAmplitude * kAmplitude / 2.0)
        << "bin " << bin;
  }
}

TEST(ResidualTests, WelchPsdOfWhiteNoiseIsFlatAtTwoSigmaSquaredOverFs) {
  constexpr double kFs = 200.0, kSigma = 0.5;
  constexpr std::size_t kSegment = 128, kN = 1u << 16;
  const Spectrum psd = welch_psd(white_noise(31, kN, kSigma), kFs, kSegment);
  ASSERT_EQ(psd.value.size(), kSegment / 2 + 1);
  const double level = 2.0 * kSigma * kSigma / kFs;  // one-sided
  // 1023 half-overlapping Hann segments: each bin averages about 1023 / 1.06 independent
  // chi^2_2 / 2 values (the 1.06 for the overlap's correlation of 1/6), relative standard
  // error 3.2 %. 15 % per bin is 4.7 of those; the mean over 62 bins, within 2 %, is 4 of its
  // own (neighbouring Hann bins are correlated, 62 bins count as about 40).
  // Bins 0 and 1 are checked apart, below.
  double sum = 0.0;
  for (std::size_t k = 2; k < kSegment / 2; ++k) {
    EXPECT_NEAR(psd.value[k] / level, 1.0, 0.15) << "bin " << k;
    sum += psd.value[k];
  }
  EXPECT_NEAR(sum / (kSegment / 2 - 2) / level, 1.0, 0.02);
  // The Nyquist bin has no mirror image and is not doubled: sigma^2 / fs. Being real, it has
  // chi^2_1 per segment: relative standard error 4.5 %; 20 % is 4.4 of them.
  EXPECT_NEAR(psd.value[kSegment / 2] / (level / 2.0), 1.0, 0.2);
  // Removing each segment's mean (m, variance sigma^2 / N) also removes from bins 0 and 1 the
  // part the Hann window ties to it (the window's DFT W is N/2 at bin 0, -N/4 at bin 1):
  // E|X_k|^2 = sigma^2 (sum w^2 - |W_k|^2 / N) = sigma^2 (3N/8 - N/4) at bin 0 (not doubled,
  // 1/6 of the level) and sigma^2 (3N/8 - N/16) at bin 1 (5/6 of the level). Bin 0 is real:
  // 4.5 % relative standard error, 20 % is 4.4 of them; bin 1: 3.2 %, 15 % is 4.7.
  EXPECT_NEAR(psd.value[0] / (level / 6.0), 1.0, 0.2);
  EXPECT_NEAR(psd.value[1] / (level * 5.0 / 6.0), 1.0, 0.15);
}

TEST(ResidualTests, WelchPsdNeedsAPowerOfTwoSegmentAndOneFullSegment) {
  EXPECT_THROW(welch_psd(std::vector<double>(1000, 0.0), 100.0, 100), std::invalid_argument);
  EXPECT_THROW(welch_psd(std::vector<double>(1000, 0.0), 100.0, 8), std::invalid_argument);
  EXPECT_TRUE(welch_psd(std::vector<double>(63, 1.0), 100.0, 64).value.empty());
  EXPECT_EQ(welch_psd(std::vector<double>(64, 1.0), 100.0, 64).value.size(), 33u);
}

TEST(ResidualTests, CoherenceOfAFilteredCopyIsNearOne) {
  // y(n) = x(n) + 0.5 x(n-1): a linear filter whose gain is at least 0.5 at every frequency,
  // so x and y are perfectly coherent; what keeps the estimate below 1 is only the one sample
  // at each segment's start whose x(n-1) lies outside the segment, which the Hann window
  // all but removes.
  constexpr double kFs = 100.0;
  constexpr std::size_t kSegment = 256, kN = 8192;
  const std::vector<double> x = white_noise(41, kN, 1.0);
  std::vector<double> y(kN);
  y[0] = x[0];
  for (std::size_t i = 1; i < kN; ++i) y[i] = x[i] + 0.5 * x[i - 1];
  const Spectrum msc = coherence(x, y, kFs, kSegment);
  ASSERT_EQ(msc.value.size(), kSegment / 2 + 1);
  EXPECT_EQ(msc.frequency_hz, welch_psd(x, kFs, kSegment).frequency_hz);
  for (std::size_t k = 1; k < msc.value.size(); ++k) {
    EXPECT_GT(msc.value[k], 0.99) << "bin " << k;
    EXPECT_LE(msc.value[k], 1.0 + 1e-12) << "bin " << k;
  }
}

TEST(ResidualTests, CoherenceOfACopyInEqualNoiseIsOneHalf) {
  // y = x + w, w independent of x with x's variance: |S_xy|^2 / (S_xx S_yy) = S^2 / (S 2S) = 1/2
  // at every frequency. The estimate from K = 63 segments is biased up by about (1 - C)^2 / K
  // = 0.004 and scatters by about sqrt(2 / K) C (1 - C) / sqrt(C) = 0.06 per bin; the mean of
  // 127 bins (about 85 independent) is within 0.04 of 1/2 by over 5 standard errors.
  constexpr std::size_t kSegment = 256, kN = 8192;
  const std::vector<double> x = white_noise(51, kN, 1.0);
  std::vector<double> y = white_noise(52, kN, 1.0);
  for (std::size_t i = 0; i < kN; ++i) y[i] += x[i];
  const Spectrum msc = coherence(x, y, 1.0, kSegment);
  double sum = 0.0;
  for (std::size_t k = 1; k < kSegment / 2; ++k) sum += msc.value[k];
  EXPECT_NEAR(sum / (kSegment / 2 - 1), 0.5, 0.04);
}

TEST(ResidualTests, CoherenceOfIndependentNoisesIsAboutOneOverTheSegments) {
  // For independent series the estimate's expectation is about 1 / K_eff, K_eff = K / 1.06 for
  // K half-overlapping Hann segments: here K = (8192 - 256) / 128 + 1 = 63, 1 / K_eff = 0.017.
  // Per bin it is about Beta(1, K_eff - 1), standard deviation 0.017; the mean of 127 bins
  // must lie within [0.5, 2] / K (0.008..0.032), many standard errors of the mean either way.
  // No bin should exceed 0.2: P(Beta(1, 59) > 0.2) = 0.8^58 = 2e-6 per bin.
  constexpr std::size_t kSegment = 256, kN = 8192, kSegments = (kN - kSegment) / (kSegment / 2) + 1;
  const Spectrum msc = coherence(white_noise(61, kN, 1.0), white_noise(62, kN, 2.0), 1.0, kSegment);
  double sum = 0.0, peak = 0.0;
  for (std::size_t k = 1; k < kSegment / 2; ++k) {
    sum += msc.value[k];
    peak = std::max(peak, msc.value[k]);
    EXPECT_GE(msc.value[k], 0.0);
  }
  const double mean = sum / (kSegment / 2 - 1);
  EXPECT_GT(mean, 0.5 / kSegments);
  EXPECT_LT(mean, 2.0 / kSegments);
  EXPECT_LT(peak, 0.2);
}

TEST(ResidualTests, SpectrumSegmentIsTheLargestPowerOfTwoUpToAnEighthWithin16And256) {
  EXPECT_EQ(spectrum_segment(0), 16u);
  EXPECT_EQ(spectrum_segment(100), 16u);
  EXPECT_EQ(spectrum_segment(255), 16u);   // 255 / 8 = 31
  EXPECT_EQ(spectrum_segment(256), 32u);   // 256 / 8 = 32
  EXPECT_EQ(spectrum_segment(1000), 64u);  // 125
  EXPECT_EQ(spectrum_segment(1024), 128u);
  EXPECT_EQ(spectrum_segment(2047), 128u);  // 255
  EXPECT_EQ(spectrum_segment(2048), 256u);
  EXPECT_EQ(spectrum_segment(1000000), 256u);
}

// ---- mean_change_points ------------------------------------------------------------------------

// The segments tile [0, n) in order.
void expect_tiling(const std::vector<MeanSegment>& segments, std::size_t n) {
  ASSERT_FALSE(segments.empty());
  EXPECT_EQ(segments.front().begin, 0u);
  EXPECT_EQ(segments.back().end, n);
  for (std::size_t i = 1; i < segments.size(); ++i) {
    EXPECT_EQ(segments[i].begin, segments[i - 1].end);
  }
}

TEST(ResidualTests, MeanChangePointsFindsAStepAtItsIndexAndItsTwoMeans) {
  // A step of 4 sigma at sample 600 of 1000.
  constexpr std::size_t kN = 1000, kStep = 600;
  constexpr double kSigma = 0.25, kShift = 1.0;
  for (std::uint64_t seed = 0; seed < 20; ++seed) {
    std::vector<double> x = white_noise(8000 + seed, kN, kSigma);
    for (std::size_t i = kStep; i < kN; ++i) x[i] += kShift;
    const std::vector<MeanSegment> s = mean_change_points(x, kSigma, 0.5 * kSigma, 20, 8);
    ASSERT_EQ(s.size(), 2u) << "seed " << seed;
    expect_tiling(s, kN);
    // Each sample past the true step on the wrong side costs the CUSUM about (shift / sigma)^2
    // = 16 noise variances: the estimate is rarely more than a sample off; 3 allows for it.
    EXPECT_NEAR(static_cast<double>(s[0].end), static_cast<double>(kStep), 3.0) << "seed " << seed;
    // The means of 600 and 400 samples: standard errors 0.010 and 0.0125; 0.05 is 4 of them.
    EXPECT_NEAR(s[0].mean, 0.0, 0.05) << "seed " << seed;
    EXPECT_NEAR(s[1].mean, kShift, 0.05) << "seed " << seed;
  }
}

TEST(ResidualTests, MeanChangePointsFindsNoneInPureNoise) {
  // With noise_std the true sigma and min_shift 0, a split is kept when |Z| > 4 at the split
  // that maximises |Z|, Z ~ N(0, 1) at each of the 61 split points min_length 20 allows in 100
  // samples. By the union bound, P <= 61 * 2 * (1 - Phi(4)) = 61 * 6.33e-5 = 0.39 % per series
  // (the Z's are correlated, so the true rate is lower). Over 1000 series: at most 3.9
  // expected, binomial standard deviation 2.0; more than 9 (3 standard deviations over the
  // union bound) fails. A 3-standard-error threshold gives 25 of these 1000 series a split
  // (measured by passing noise_std 0.75), so the check tells 3 from 4 standard errors.
  constexpr std::size_t kN = 100, kSeeds = 1000;
  std::size_t with_a_split = 0;
  for (std::uint64_t seed = 0; seed < kSeeds; ++seed) {
    const std::vector<double> x = white_noise(9000 + seed, kN, 1.0);
    const std::vector<MeanSegment> s = mean_change_points(x, 1.0, 0.0, 20, 8);
    expect_tiling(s, kN);
    if (s.size() > 1) ++with_a_split;
    if (s.size() == 1) {
      EXPECT_NEAR(s[0].mean, mean_of(x), 1e-12);
    }
  }
  EXPECT_LE(with_a_split, 9u);
}

TEST(ResidualTests, MeanChangePointsIgnoresAShiftNoLargerThanMinShift) {
  // A step of 0.3 is 42 standard errors of the two means (sigma 0.05, 500 samples a side), so
  // only min_shift decides.
  constexpr std::size_t kN = 1000;
  std::vector<double> x = white_noise(10000, kN, 0.05);
  for (std::size_t i = kN / 2; i < kN; ++i) x[i] += 0.3;
  EXPECT_EQ(mean_change_points(x, 0.05, 0.4, 20, 8).size(), 1u);
  EXPECT_EQ(mean_change_points(x, 0.05, 0.2, 20, 8).size(), 2u);
}

TEST(ResidualTests, MeanChangePointsRespectsMinLength) {
  // A 20-sigma step at sample 10 of 400. Allowed to, the split lands on it; with min_length 30
  // it cannot, and the best allowed split is the nearest, at 30: the between-segment score
  // n_l n_r / n (m_l - m_r)^2 with m_l = 50 / n_l, m_r = 0 is 2500 n_r / (n n_l), falling with
  // n_l. [0, 30) is then shorter than 2 * 30 and not split again.
  constexpr std::size_t kN = 400;
  std::vector<double> x = white_noise(11000, kN, 0.25);
  for (std::size_t i = 0; i < 10; ++i) x[i] += 5.0;
  const std::vector<MeanSegment> free = mean_change_points(x, 0.25, 0.1, 5, 8);
  ASSERT_EQ(free.size(), 2u);
  EXPECT_EQ(free[0].end, 10u);
  const std::vector<MeanSegment> held = mean_change_points(x, 0.25, 0.1, 30, 8);
  ASSERT_EQ(held.size(), 2u);
  expect_tiling(held, kN);
  EXPECT_EQ(held[0].end, 30u);
  // Fewer than 2 * min_length samples are never split, however large the step.
  const std::vector<double> short_x(x.begin(), x.begin() + 59);
  EXPECT_EQ(mean_change_points(short_x, 0.25, 0.1, 30, 8).size(), 1u);
  // Every segment of a noisy staircase is at least min_length long.
  std::vector<double> stairs = white_noise(11001, 2000, 1.0);
  for (std::size_t i = 0; i < stairs.size(); ++i) stairs[i] += static_cast<double>(i / 37) * 2.0;
  const std::vector<MeanSegment> s = mean_change_points(stairs, 1.0, 0.0, 50, 100);
  expect_tiling(s, stairs.size());
  EXPECT_GT(s.size(), 10u);
  for (const MeanSegment& segment : s) EXPECT_GE(segment.end - segment.begin, 50u);
}

// Levels 0, 1, 2, 3, 4 over 200 samples each, sigma 0.1: every step is 10 sigma.
std::vector<double> staircase() {
  std::vector<double> x = white_noise(12000, 1000, 0.1);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] += static_cast<double>(i / 200);
  return x;
}

TEST(ResidualTests, MeanChangePointsRespectsMaxSegments) {
  const std::vector<double> x = staircase();
  const std::vector<MeanSegment> all = mean_change_points(x, 0.1, 0.05, 20, 8);
  ASSERT_EQ(all.size(), 5u);
  expect_tiling(all, x.size());
  for (std::size_t i = 0; i < 5; ++i) {
    // 10-sigma steps: the CUSUM lands on them (see above); means of 200 samples, standard
    // error 0.007.
    EXPECT_NEAR(static_cast<double>(all[i].begin), 200.0 * static_cast<double>(i), 2.0);
    EXPECT_NEAR(all[i].mean, static_cast<double>(i), 0.03);
  }
  for (std::size_t cap = 1; cap <= 5; ++cap) {
    const std::vector<MeanSegment> s = mean_change_points(x, 0.1, 0.05, 20, cap);
    EXPECT_EQ(s.size(), cap) << "max_segments " << cap;
    expect_tiling(s, x.size());
    // A segment's mean is the mean of its samples, also when a cap merged several levels.
    for (const MeanSegment& segment : s) {
      const std::vector<double> part(x.begin() + static_cast<std::ptrdiff_t>(segment.begin),
                                     x.begin() + static_cast<std::ptrdiff_t>(segment.end));
      EXPECT_NEAR(segment.mean, mean_of(part), 1e-12);
    }
  }
  EXPECT_NEAR(mean_change_points(x, 0.1, 0.05, 20, 1)[0].mean, 2.0, 0.02);
}

TEST(ResidualTests, MeanChangePointsKeepsTheLargestShiftsWhenCapped) {
  // Levels 0, 1, 11, 21 over 250 samples each. The first split is at 500 (between-segment
  // score 250 * 15.5^2 against 187.5 * 17^2 at 750 and 187.5 * 11^2 at 250). With
  // max_segments 3 the second cut kept should be the coarser one, the 10-unit step at 750, not
  // the 1-unit step at 250.
  std::vector<double> x = white_noise(13000, 1000, 0.1);
  const double levels[] = {0.0, 1.0, 11.0, 21.0};
  for (std::size_t i = 0; i < x.size(); ++i) x[i] += levels[i / 250];
  const std::vector<MeanSegment> s = mean_change_points(x, 0.1, 0.05, 20, 3);
  ASSERT_EQ(s.size(), 3u);
  EXPECT_NEAR(static_cast<double>(s[0].end), 500.0, 2.0);
  EXPECT_NEAR(static_cast<double>(s[1].end), 750.0, 2.0);
  // Means of 500, 250 and 250 samples of sigma 0.1: standard errors under 0.01.
  EXPECT_NEAR(s[0].mean, 0.5, 0.05);
  EXPECT_NEAR(s[1].mean, 11.0, 0.05);
  EXPECT_NEAR(s[2].mean, 21.0, 0.05);
}

}  // namespace
}  // namespace flange::diagnose
