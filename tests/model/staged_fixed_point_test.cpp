// SPDX-License-Identifier: MIT
// The partly fixed-point filter cannot drift from the contract: with every effect on it equals
// IirCore word for word on every coefficient set (saturating and wrapping inputs included); with
// every effect off it equals the double-precision ReferenceFilter within double rounding; each
// effect on its own changes the output.
#include "staged_fixed_point.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "filter_json.h"
#include "iir_core.h"
#include "reference_filter.h"

namespace flange::model {
namespace {
namespace fs = std::filesystem;

// Every coefficient set in the tree: the checked-in ones and the generated test sets.
std::vector<fs::path> all_sets() {
  std::vector<fs::path> sets;
  for (const char* root : {"coeffs", "tests/data/coeffs"}) {
    for (const auto& entry : fs::directory_iterator(fs::path(FLANGE_SOURCE_DIR) / root)) {
      if (fs::is_regular_file(entry.path() / "filter.json")) sets.push_back(entry.path());
    }
  }
  std::sort(sets.begin(), sets.end());
  return sets;
}

// Inputs in LSB, some fractional (so input rounding matters), some full scale (so the sections
// saturate), some square (so narrow filters ring up to the rails).
std::vector<std::vector<double>> stimuli(int sample_width, std::uint64_t seed) {
  const double fs = std::ldexp(1.0, sample_width - 1);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<double> half, full, square, sine;
  for (int n = 0; n < 4000; ++n) {
    half.push_back(0.5 * fs * unit(rng));
    full.push_back(fs * unit(rng));
    square.push_back((n / 300) % 2 == 0 ? fs - 1 : -fs);
    sine.push_back(0.7 * fs * std::sin(2 * std::numbers::pi * 0.0007 * n * n / 40));
  }
  std::vector<double> impulse(2000, 0.0);
  impulse[0] = fs - 1;
  return {half, full, square, sine, impulse};
}

std::string where(const fs::path& set, std::size_t stimulus, std::size_t n) {
  return fmt::format("{} stimulus {} sample {} (ctest -R StagedFixedPoint)", set.string(), stimulus,
                     n);
}

TEST(StagedFixedPoint, AllEffectsOnEqualsIirCoreOnEverySet) {
  const std::vector<fs::path> sets = all_sets();
  ASSERT_GE(sets.size(), 9u) << "the three checked-in sets and six generated ones";
  for (const fs::path& set : sets) {
    const CoreConfig config = load_core_config(set / "filter.json");
    const FloatDesign design = load_float_design(set / "filter.json");
    const auto inputs = stimuli(config.sample_width, 7);
    for (std::size_t s = 0; s < inputs.size(); ++s) {
      IirCore core(config);
      StagedFixedPoint staged(config, design, EffectSet::all());
      bool saturated = false;
      for (std::size_t n = 0; n < inputs[s].size(); ++n) {
        const double x = inputs[s][n];
        const StepResult r = core.step(round_input_sample(x, config.sample_width));
        saturated = saturated || r.saturated;
        ASSERT_EQ(staged.step(x), static_cast<double>(r.sample)) << where(set, s, n);
      }
      // The full-scale square wave drives the overshoot of every Butterworth low-pass of order
      // >= 2 into the rails (a first-order one does not overshoot, nor does a cascade of
      // first-order sections: its poles are real).
      const bool real_poles_only = config.section_order == 1 && config.num_sections > 1;
      if (s == 2 && config.filter_order >= 2 && !real_poles_only) {
        EXPECT_TRUE(saturated) << where(set, s, 0) << ": meant to saturate";
      }
    }
  }
}

// A biquad with an accumulator too narrow for its worst case: IirCore wraps, and so must the
// staged filter, and only with kAccumulatorWrap.
TEST(StagedFixedPoint, AccumulatorWrapFollowsIirCore) {
  CoreConfig config;
  config.name = "narrow_accumulator";
  config.filter_order = 2;
  config.num_sections = 1;
  config.section_order = 2;
  config.sample_width = 16;
  config.coef_width = 18;
  config.coef_frac_bits = 16;
  config.feedback_shift = 0;
  config.acc_width = 34;  // D + s + C; the worst case needs 35 bits
  // b = 1.99, 1.99, 1.99; -a = 1.6, -0.8 (poles at radius 0.89), hi words only; E = (2, -1).
  config.rom = {0, 0, 0, 0, 0, 130417, 130417, 130417, 104858, -52429, 2, -1};
  FloatDesign design;
  design.name = config.name;
  design.fs_hz = 1.0;
  design.sos = {{1.99, 1.99, 1.99, 1.0, -1.6, 0.8}};
  design.b = {1.99, 1.99, 1.99};
  design.a = {1.0, -1.6, 0.8};

  IirCore core(config);
  StagedFixedPoint staged(config, design, EffectSet::all());
  EffectSet no_wrap = EffectSet::none();
  for (FixedPointEffect e : kAllFixedPointEffects) {
    if (e != FixedPointEffect::kAccumulatorWrap) no_wrap = no_wrap.with(e);
  }
  StagedFixedPoint unwrapped(config, design, no_wrap);
  int differ = 0;
  for (int n = 0; n < 2000; ++n) {
    const double x = (n / 7) % 2 == 0 ? 32767.0 : -32768.0;
    const StepResult r = core.step(static_cast<std::int32_t>(x));
    ASSERT_EQ(staged.step(x), static_cast<double>(r.sample)) << "sample " << n;
    if (unwrapped.step(x) != r.sample) ++differ;
  }
  EXPECT_GT(differ, 0) << "the stimulus never wrapped the 34-bit accumulator";
}

TEST(StagedFixedPoint, AllEffectsOffEqualsReferenceFilter) {
  for (const fs::path& set : all_sets()) {
    const CoreConfig config = load_core_config(set / "filter.json");
    const FloatDesign design = load_float_design(set / "filter.json");
    const bool cascade = config.section_order == 2 &&
                         design.sos.size() == static_cast<std::size_t>(config.num_sections);
    const double full_scale = std::ldexp(1.0, config.sample_width - 1);
    for (const auto& input : stimuli(config.sample_width, 11)) {
      ReferenceFilter reference(
          design, cascade ? ReferenceFilter::Form::kSos : ReferenceFilter::Form::kDirect);
      StagedFixedPoint staged(config, design, EffectSet::none());
      double peak = 0.0, worst = 0.0;
      for (double x : input) {
        const double ref = reference.step(x / full_scale);
        const double ours = design.leftover_gain * staged.step(x) / full_scale;
        peak = std::max(peak, std::abs(ref));
        worst = std::max(worst, std::abs(ours - ref));
      }
      // Double rounding only: the staged filter sums in long double, the reference in double.
      EXPECT_LE(worst, 1e-9 * std::max(peak, 1.0)) << set.string();
    }
  }
}

TEST(StagedFixedPoint, EveryEffectAloneChangesTheOutput) {
  const fs::path set = fs::path(FLANGE_SOURCE_DIR) / "coeffs" / "vehicle_sos";
  const CoreConfig config = load_core_config(set / "filter.json");
  const FloatDesign design = load_float_design(set / "filter.json");
  const auto inputs = stimuli(config.sample_width, 3);
  for (FixedPointEffect e : kAllFixedPointEffects) {
    if (e == FixedPointEffect::kAccumulatorWrap) continue;  // never with legal samples here
    bool changed = false;
    for (const auto& input : inputs) {
      StagedFixedPoint off(config, design, EffectSet::none());
      StagedFixedPoint on(config, design, EffectSet::none().with(e));
      for (double x : input) changed = (on.step(x) != off.step(x)) || changed;
    }
    EXPECT_TRUE(changed) << effect_name(e);
  }
}

TEST(StagedFixedPoint, MismatchedShapesAreRefused) {
  const StagedFormat format;
  std::vector<SectionCoefficients> one = {{{1.0, 0.5}, {1.0, -0.5}, {0}}};
  std::vector<SectionCoefficients> other = {{{1.0, 0.5, 0.1}, {1.0, -0.5, 0.0}, {0, 0}}};
  EXPECT_THROW(StagedFixedPoint(format, one, other, EffectSet::none()), std::invalid_argument);
  EXPECT_THROW(StagedFixedPoint(format, one, {}, EffectSet::none()), std::invalid_argument);
}

}  // namespace
}  // namespace flange::model
