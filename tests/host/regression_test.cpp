// SPDX-License-Identifier: MIT
// The regression stage: terms, exact recovery, order selection, degenerate data.
#include "regression.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "input_error.h"

namespace flange::host {
namespace {

// Clearance from voltage and temperature by the thesis's eq. 3.14.
double eq_3_14(double v, double t) {
  return 1.16 + 0.3672 * v - 0.0036 * t + 0.05812 * v * v + 0.0006618 * v * t;
}

CalibrationData bench_like(std::size_t n, double noise_mm, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0.0, noise_mm);
  CalibrationData data;
  for (std::size_t k = 0; k < n; ++k) {
    const double v = 0.5 + 9.0 * static_cast<double>(k % 97) / 96.0;
    const double t = 20.0 + 78.0 * static_cast<double>((k * 7) % 101) / 100.0;
    data.voltage_v.push_back(v);
    data.temp_c.push_back(t);
    data.clearance_mm.push_back(eq_3_14(v, t) + (noise_mm > 0 ? noise(rng) : 0.0));
  }
  return data;
}

TEST(Regression, OrderTwoIsTheThesisForm) {
  const auto terms = regression_terms(2);
  const std::vector<std::pair<int, int>> expected = {{0, 0}, {0, 1}, {1, 0}, {1, 1}, {2, 0}};
  EXPECT_EQ(terms, expected);
  // Each order's terms are a prefix of the next order's.
  for (int order = 1; order < kMaxRegressionOrder; ++order) {
    const auto lower = regression_terms(order);
    const auto higher = regression_terms(order + 1);
    ASSERT_LT(lower.size(), higher.size());
    EXPECT_TRUE(std::equal(lower.begin(), lower.end(), higher.begin()));
  }
}

TEST(Regression, RecoversEquation314ExactlyWithoutNoise) {
  const RegressionFit fit = fit_regression(bench_like(2000, 0.0, 1), RegressionOptions{});
  EXPECT_EQ(fit.model.order(), 2);
  const std::vector<double> raw = fit.model.raw_coefficients();
  // Terms of order 2: 1, T, V, V T, V^2.
  EXPECT_NEAR(raw[0], 1.16, 1e-9);
  EXPECT_NEAR(raw[1], -0.0036, 1e-11);
  EXPECT_NEAR(raw[2], 0.3672, 1e-10);
  EXPECT_NEAR(raw[3], 0.0006618, 1e-12);
  EXPECT_NEAR(raw[4], 0.05812, 1e-11);
  EXPECT_NEAR(fit.model.clearance_mm(5.0, 60.0), eq_3_14(5.0, 60.0), 1e-9);
  EXPECT_GT(fit.stats.r, 0.9999);
}

TEST(Regression, NoiseDoesNotPushTheOrderUp) {
  const RegressionFit fit = fit_regression(bench_like(3000, 0.05, 2), RegressionOptions{});
  EXPECT_EQ(fit.model.order(), 2) << fit.selection;
  EXPECT_NEAR(fit.stats.rmse_mm, 0.05, 0.005);
  EXPECT_NEAR(fit.stats.heldout_mae_mm, 0.05 * std::sqrt(2.0 / M_PI), 0.005);
  ASSERT_GE(fit.candidates.size(), 3u);
  // Order 1 misses the V^2 curvature by far more than the noise.
  EXPECT_GT(fit.candidates[0].stats.heldout_mae_mm, 3 * fit.stats.heldout_mae_mm);
}

// A coil whose voltage saturates exponentially with clearance, V = 13 (1 - exp(-d / 9 mm)): its
// inverse, a logarithm, departs from a cubic in V by less than the noise here, so the fourth
// order cuts the held-out MAE by a few per cent only; yet the cubic reads a change of clearance
// a few per cent short or long, which a wear rate carries whole.
TEST(Regression, AMisfitUnderTheNoiseStillRaisesTheOrder) {
  std::mt19937_64 rng(12);
  std::normal_distribution<double> noise(0.0, 0.06);
  const auto volts_at = [](double d) { return 13.0 * (1.0 - std::exp(-d / 9.0)); };
  CalibrationData data;
  for (std::size_t k = 0; k < 20000; ++k) {
    const double d = 1.0 + 10.0 * static_cast<double>(k % 89) / 88.0;
    data.voltage_v.push_back(volts_at(d));
    data.temp_c.push_back(5.0 + 57.0 * static_cast<double>((k * 7) % 101) / 100.0);
    data.clearance_mm.push_back(d + noise(rng));
  }
  const RegressionFit fit = fit_regression(data, RegressionOptions{});
  ASSERT_GE(fit.candidates.size(), 4u);
  const double mae3 = fit.candidates[2].stats.heldout_mae_mm;
  const double mae4 = fit.candidates[3].stats.heldout_mae_mm;
  EXPECT_LT(mae3 - mae4, 0.05 * mae3) << "the misfit should hide under the noise";
  EXPECT_EQ(fit.model.order(), 4) << fit.selection;
  // The chosen curve reads a change of clearance within 1 % of the truth over the range.
  const auto read = [&](double at) { return fit.model.clearance_mm(volts_at(at), 30.0); };
  for (double d = 2.5; d <= 8.5; d += 1.0) {
    EXPECT_NEAR((read(d + 0.25) - read(d - 0.25)) / 0.5, 1.0, 0.01) << "at " << d << " mm";
  }
}

TEST(Regression, DegenerateDataIsRefused) {
  CalibrationData too_few = bench_like(10, 0.0, 3);
  EXPECT_THROW(fit_regression(too_few, RegressionOptions{}), InputError);
  CalibrationData constant_t = bench_like(500, 0.01, 4);
  for (double& t : constant_t.temp_c) t = 25.0;
  try {
    fit_regression(constant_t, RegressionOptions{});
    FAIL() << "constant temperature accepted";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("temp_c is constant"), std::string::npos);
  }
  CalibrationData collinear = bench_like(500, 0.01, 5);
  for (std::size_t k = 0; k < collinear.temp_c.size(); ++k) {
    collinear.temp_c[k] = 20.0 + 8.0 * collinear.voltage_v[k];  // T moves with V
  }
  try {
    fit_regression(collinear, RegressionOptions{});
    FAIL() << "collinear data accepted";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("move together"), std::string::npos);
  }
  // Nearly collinear: the temperature follows the voltage to within 6 mK.
  CalibrationData nearly = collinear;
  for (std::size_t k = 0; k < nearly.temp_c.size(); ++k) {
    nearly.temp_c[k] += 0.006 * std::sin(0.7 * static_cast<double>(k));
  }
  try {
    fit_regression(nearly, RegressionOptions{});
    FAIL() << "nearly collinear data accepted";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("at least 1 % is needed"), std::string::npos)
        << error.what();
  }
}

TEST(Regression, TheThesisRuleRaisesTheOrderUntilRReachesTheThreshold) {
  CalibrationData data = bench_like(2000, 0.0, 6);
  for (std::size_t k = 0; k < data.clearance_mm.size(); ++k) {
    const double v = data.voltage_v[k];
    data.clearance_mm[k] += 0.02 * v * v * v;  // a cubic term the thesis form lacks
  }
  RegressionOptions options;
  options.min_r = 0.99999999;
  const RegressionFit fit = fit_regression(data, options);
  EXPECT_GE(fit.model.order(), 3) << fit.selection;
  EXPECT_GE(fit.stats.r, options.min_r);
}

}  // namespace
}  // namespace flange::host

namespace flange::host {
namespace {

TEST(Regression, ARegimeSeenOnlyOnceStillCrossValidates) {
  // The heating happens in the first fifth only; afterwards the temperature stays at 20 C.
  CalibrationData data = bench_like(20000, 0.05, 7);
  for (std::size_t k = 4000; k < data.temp_c.size(); ++k) {
    data.temp_c[k] = 20.0;
    const double v = data.voltage_v[k];
    data.clearance_mm[k] = eq_3_14(v, 20.0);
  }
  const RegressionFit fit = fit_regression(data, RegressionOptions{});
  EXPECT_EQ(fit.model.order(), 2) << fit.selection;
  EXPECT_LT(fit.stats.heldout_mae_mm, 0.1);
}

}  // namespace
}  // namespace flange::host
