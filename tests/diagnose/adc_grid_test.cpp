// SPDX-License-Identifier: MIT
// The converter grid estimated from a voltage column (any LSB, any origin, with noise and a few
// odd values, or none at all) and the noise estimate that survives a coarse grid, where the
// median of lag-2 differences collapses.
#include "adc_grid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "quantised_noise.h"
#include "series_statistics.h"
#include "white_noise.h"

namespace flange::diagnose {
namespace {

constexpr double kFsHz = 6.0;
constexpr int kSamples = 39600;  // 6600 s at 6 Hz, the bench protocol's length

// A slowly varying analog voltage like a bench session's: a 240 s sweep over most of the range
// with a slow drift (a twin's noise-free voltage stands in for it).
std::vector<double> analog_signal() {
  std::vector<double> v(kSamples);
  for (int i = 0; i < kSamples; ++i) {
    const double t = i / kFsHz;
    v[static_cast<std::size_t>(i)] = 5.0 + 3.8 * std::sin(2.0 * std::numbers::pi * t / 240.0) +
                                     0.4 * std::sin(2.0 * std::numbers::pi * t / 3600.0);
  }
  return v;
}

struct Converter {
  int bits;
  double lo, hi;
  double lsb() const { return (hi - lo) / std::ldexp(1.0, bits); }
};

void PrintTo(const Converter& c, std::ostream* out) {
  *out << c.bits << " bits over [" << c.lo << ", " << c.hi << "] V";
}

// `analog` plus white noise through the converter (rounding, clamped), written with the
// recording format's six decimals; `odd_share` of the samples replaced by off-grid glitches.
std::vector<double> record(const std::vector<double>& analog, double noise_v, const Converter& c,
                           double odd_share, unsigned seed) {
  std::mt19937_64 random(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double top = std::ldexp(1.0, c.bits) - 1.0;
  std::vector<double> v(analog.size());
  for (std::size_t i = 0; i < analog.size(); ++i) {
    const double code =
        std::clamp(std::round((analog[i] + noise_v * normal(random) - c.lo) / c.lsb()), 0.0, top);
    v[i] = std::round((c.lo + code * c.lsb()) * 1e6) / 1e6;
    if (unit(random) < odd_share) v[i] = std::round((analog[i] + 0.37 * c.lsb()) * 1e6) / 1e6;
  }
  return v;
}

class GridOf : public ::testing::TestWithParam<Converter> {};

TEST_P(GridOf, IsFoundFromTheSpacingWithAndWithoutNoiseAndOddValues) {
  const Converter c = GetParam();
  const std::vector<double> analog = analog_signal();
  for (const double noise_v : {0.0, 0.01, 0.05}) {
    for (const double odd_share : {0.0, 0.01}) {
      const std::vector<double> v = record(analog, noise_v, c, odd_share, 7);
      const std::optional<AdcGrid> grid = estimate_adc_grid(v);
      const std::string where = testing::PrintToString(noise_v) + " V noise, " +
                                testing::PrintToString(odd_share) + " odd";
      ASSERT_TRUE(grid.has_value()) << where;
      EXPECT_NEAR(grid->lsb_v, c.lsb(), 1e-3 * c.lsb()) << where;
      const double codes_from_lo = (grid->lowest_v - c.lo) / c.lsb();
      EXPECT_NEAR(codes_from_lo, std::round(codes_from_lo), 0.01) << where;
      EXPECT_GE(grid->share_on_grid, 0.98) << where;
      EXPECT_LE(grid->codes_used, std::ldexp(1.0, c.bits)) << where;
      // The twin's converter on that grid reproduces every code but the odd values.
      std::size_t reproduced = 0;
      for (const double x : v) reproduced += std::abs(grid->quantise(x) - x) <= 2e-6 ? 1 : 0;
      EXPECT_GE(static_cast<double>(reproduced),
                (0.995 - odd_share) * static_cast<double>(v.size()))
          << where;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(
    BitsAndRanges, GridOf,
    ::testing::Values(Converter{4, 0.0, 10.24}, Converter{6, -5.0, 5.0}, Converter{8, 0.0, 12.0},
                      Converter{10, -10.24, 10.24}, Converter{12, 0.0, 10.24},
                      Converter{6, 0.0, 10.24}, Converter{10, -5.0, 5.0},
                      Converter{12, -10.0, 10.0}, Converter{8, 0.0, 5.12}),
    [](const auto& param_info) {
      return "Bits" + std::to_string(param_info.param.bits) + "From" +
             std::to_string(static_cast<int>(std::round(100 * (param_info.param.lo + 20)))) + "To" +
             std::to_string(static_cast<int>(std::round(100 * param_info.param.hi)));
    });

TEST(AdcGrid, AUsualRangeIsNamedAndAnyOtherIsModelledFromTheLowestCode) {
  const std::vector<double> analog = analog_signal();
  const auto usual = estimate_adc_grid(record(analog, 0.02, {12, -10.0, 10.0}, 0.0, 3));
  ASSERT_TRUE(usual.has_value());
  EXPECT_TRUE(usual->usual_range);
  EXPECT_EQ(usual->bits, 12);
  EXPECT_EQ(usual->v_min, -10.0);
  EXPECT_EQ(usual->v_max, 10.0);
  const auto other = estimate_adc_grid(record(analog, 0.02, {6, 0.0, 10.24}, 0.0, 3));
  ASSERT_TRUE(other.has_value());
  EXPECT_FALSE(other->usual_range);
  EXPECT_NEAR(other->v_min, other->lowest_v, 1e-12);
  EXPECT_GE(std::ldexp(1.0, other->bits), static_cast<double>(other->codes_spanned));
  const sim::EffectSettings effect = other->as_effect();
  EXPECT_EQ(effect.name, "adc_quantization");
}

TEST(AdcGrid, AnUnquantisedColumnHasNone) {
  const std::vector<double> analog = analog_signal();
  std::mt19937_64 random(5);
  std::normal_distribution<double> normal(0.0, 1.0);
  for (const double noise_v : {0.0, 0.001, 0.01, 0.07}) {
    std::vector<double> v = analog;
    for (double& x : v) x = std::round((x + noise_v * normal(random)) * 1e6) / 1e6;
    EXPECT_FALSE(estimate_adc_grid(v).has_value()) << noise_v;
  }
}

// The stated tolerance: the analog noise behind a coarse grid within 15 % whenever it is at
// least a twentieth of the LSB (below that the codes hardly ever flicker and it is known within a
// factor of two), where the median of lag-2 differences misreads it by half or more.
TEST(QuantisedNoise, SurvivesACoarseGridWhereTheMedianCollapses) {
  const std::vector<double> analog = analog_signal();
  int misread = 0;
  for (const Converter c : {Converter{4, 0.0, 10.24}, Converter{6, -5.0, 5.0},
                            Converter{8, 0.0, 10.24}, Converter{10, 0.0, 12.0}}) {
    for (const double noise_v : {0.01, 0.03, 0.1}) {
      const std::vector<double> v = record(analog, noise_v, c, 0.0, 11);
      const auto grid = estimate_adc_grid(v);
      ASSERT_TRUE(grid.has_value());
      const WhiteNoise noise = estimate_white_noise(v, analog, grid);
      const std::string where = std::to_string(c.bits) + " bits, LSB " + std::to_string(c.lsb()) +
                                " V, noise " + std::to_string(noise_v);
      if (noise_v >= c.lsb() / 20) {
        EXPECT_NEAR(noise.analog_std_v, noise_v, 0.15 * noise_v) << where;
      } else {
        EXPECT_GT(noise.analog_std_v, 0.5 * noise_v) << where;
        EXPECT_LT(noise.analog_std_v, 2.0 * noise_v) << where;
      }
      EXPECT_NEAR(noise.effective_std_v,
                  std::sqrt(std::pow(noise.analog_std_v, 2) + std::pow(c.lsb(), 2) / 12), 1e-9);
      std::vector<double> gap(v.size());
      for (std::size_t i = 0; i < v.size(); ++i) gap[i] = v[i] - analog[i];
      if (std::abs(white_noise_std(gap, 2) / noise_v - 1.0) > 0.5) ++misread;
    }
  }
  // What the grid-aware estimate replaces: on the coarse grids the median of lag-2 differences
  // reads the quantisation's staircase, 0.025-0.03 V whatever the noise.
  EXPECT_GE(misread, 4);
}

TEST(QuantisedNoise, NullRmsOfAQuantisedTwinMatchesASimulation) {
  std::mt19937_64 random(13);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (const double r : {0.02, 0.1, 0.5, 2.0}) {
    const double lsb = 0.16, sigma = r * lsb;
    double sum = 0.0;
    constexpr int kDraws = 200000;
    for (int k = 0; k < kDraws; ++k) {
      const double s = lsb * 100.0 * unit(random);
      const double d = lsb * (std::round((s + sigma * normal(random)) / lsb) - std::round(s / lsb));
      sum += d * d;
    }
    EXPECT_NEAR(quantised_null_rms(sigma, lsb), std::sqrt(sum / kDraws),
                0.02 * std::sqrt(sum / kDraws))
        << r;
  }
  EXPECT_NEAR(quantised_null_rms(10.0, 0.1), std::sqrt(100.0 + 0.01 / 6.0), 1e-3);
}

}  // namespace
}  // namespace flange::diagnose
