// SPDX-License-Identifier: MIT
// The mains line finding (diagnose/data/candidates/free_shapes/mains_lines.h, mains_family.h) on
// small synthetic gaps with known answers: where 50 and 60 Hz and their harmonics alias, the lines
// found there, none on pure noise, and lines whose power follows the sensor's sensitivity taken
// for motion.
#include "line_source.h"
#include "mains_lines.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "mains_family.h"
#include "synthetic_bench.h"

namespace flange::diagnose::free_shapes {
namespace {

// `noise` plus tones of (frequency, amplitude) sampled at `t`.
std::vector<double> with_tones(std::vector<double> gap, const std::vector<double>& t,
                               const std::vector<std::pair<double, double>>& tones) {
  for (std::size_t i = 0; i < gap.size(); ++i) {
    for (const auto& [hz, amplitude] : tones) {
      gap[i] += amplitude * std::sin(2.0 * std::numbers::pi * hz * t[i] + 0.7);
    }
  }
  return gap;
}

bool has_line_near(const std::vector<double>& lines, double hz, double within) {
  for (double f : lines) {
    if (std::abs(f - hz) <= within) return true;
  }
  return false;
}

TEST(MainsAliases, WhereTheMainsAndItsHarmonicsLandAtKnownRates) {
  EXPECT_DOUBLE_EQ(alias_hz(50.0, 6.0), 2.0);
  EXPECT_DOUBLE_EQ(alias_hz(100.0, 6.0), 2.0);
  EXPECT_DOUBLE_EQ(alias_hz(150.0, 6.0), 0.0);
  EXPECT_NEAR(alias_hz(60.01, 7.0), 2.99, 1e-9);
  EXPECT_NEAR(alias_hz(120.02, 7.0), 1.02, 1e-9);
  // At 6 Hz every harmonic of 50 Hz lands on 2 Hz or on 0 Hz, and every one of 60 Hz on 0 Hz.
  EXPECT_EQ(mains_aliases(6.0).distinct_hz, std::vector<double>{2.0});
  EXPECT_EQ(mains_aliases(6.0).of_harmonics.size(), 5u);  // 50 Hz's 1st, 2nd, 4th, 5th and 7th
  // At 7 Hz on 1, 2 and 3 Hz (the 7th harmonics on 0 Hz).
  EXPECT_EQ(mains_aliases(7.0).distinct_hz, (std::vector<double>{1.0, 2.0, 3.0}));
}

// A grid 0.02 Hz fast: at 6 Hz its fundamental lands on 2.02 Hz and its second harmonic on
// 1.96 Hz, both near the one alias.
TEST(MainsLineFinding, ALineAndItsHarmonicAreFoundNearTheirAlias) {
  const SyntheticBench bench;
  const std::vector<double>& t = bench.series().t_s;
  const std::vector<double> gap =
      with_tones(white_noise(t.size(), 0.02, 11), t, {{50.02, 0.05}, {100.04, 0.02}});
  const std::vector<double> lines = find_lines(t, gap, mains_aliases(6.0).distinct_hz);
  ASSERT_EQ(lines.size(), 2u) << ::testing::PrintToString(lines);
  EXPECT_TRUE(has_line_near(lines, 2.02, 0.006)) << ::testing::PrintToString(lines);
  EXPECT_TRUE(has_line_near(lines, 1.96, 0.006)) << ::testing::PrintToString(lines);
}

// At 7 Hz a 60.01 Hz grid's fundamental lands on 2.99 Hz and its second harmonic, five times
// weaker, on 1.02 Hz: both are found.
TEST(MainsLineFinding, AWeakHarmonicOnItsOwnAliasIsFoundBesideAStrongFundamental) {
  const SyntheticBench bench(7.0);
  const std::vector<double>& t = bench.series().t_s;
  const std::vector<double> gap =
      with_tones(white_noise(t.size(), 0.02, 12), t, {{60.01, 0.15}, {120.02, 0.03}});
  const std::vector<double> lines = find_lines(t, gap, mains_aliases(7.0).distinct_hz);
  ASSERT_EQ(lines.size(), 2u) << ::testing::PrintToString(lines);
  EXPECT_TRUE(has_line_near(lines, 2.99, 0.006)) << ::testing::PrintToString(lines);
  EXPECT_TRUE(has_line_near(lines, 1.02, 0.006)) << ::testing::PrintToString(lines);
}

TEST(MainsLineFinding, NoneOnPureNoise) {
  for (const double fs_hz : {6.0, 7.0}) {
    const SyntheticBench bench(fs_hz);
    const std::vector<double>& t = bench.series().t_s;
    for (std::uint64_t seed = 20; seed < 25; ++seed) {
      const std::vector<double> lines =
          find_lines(t, white_noise(t.size(), 0.02, seed), mains_aliases(fs_hz).distinct_hz);
      EXPECT_TRUE(lines.empty()) << fs_hz << " Hz, seed " << seed << ": "
                                 << ::testing::PrintToString(lines);
    }
  }
}

// Windowed tones take each window's own amplitude and phase: a line whose phase jumps between
// windows is followed.
TEST(MainsLineFinding, WindowedTonesFollowAPhaseThatChangesFromWindowToWindow) {
  const SyntheticBench bench;
  const std::vector<double>& t = bench.series().t_s;
  std::vector<double> gap(t.size());
  double phase = 0.0;
  for (const auto& [begin, end] : mains_windows(t)) {
    phase += 1.0;  // a new phase in every window
    for (std::size_t i = begin; i < end; ++i) {
      gap[i] = 0.1 * std::sin(2.0 * std::numbers::pi * 2.0 * t[i] + phase);
    }
  }
  int values = 0;
  const std::vector<double> tones = windowed_tones(t, gap, {2.0}, values);
  double left = 0.0;
  for (std::size_t i = 0; i < t.size(); ++i) left = std::max(left, std::abs(gap[i] - tones[i]));
  EXPECT_LT(left, 1e-9);
  EXPECT_EQ(values, 2 * static_cast<int>(mains_windows(t).size()));
}

// At 6 Hz the third harmonic of 50 Hz lands on 0 Hz: with a 50 Hz line found, each session's own
// constant joins the lines.
TEST(MainsFamilySearch, AHarmonicOnZeroHertzAddsEachSessionsConstant) {
  const SyntheticBench bench;
  const std::vector<double>& t = bench.series().t_s;
  const std::vector<double> gap = with_tones(white_noise(t.size(), 0.02, 13), t, {{50.0, 0.05}});
  MainsFamily mains;
  mains.search(bench.part(), gap);
  ASSERT_FALSE(mains.empty());
  EXPECT_EQ(mains.lines(), 1u);
  EXPECT_TRUE(has_line_near(mains.calibration_lines_hz(), 2.0, 0.006));
  EXPECT_EQ(mains.dc_harmonic_hz(), 150.0);
  const FreeShapeFit fit = mains.fit({bench.part(), bench.part(), gap, gap, false});
  EXPECT_EQ(fit.free_values, 3);
  EXPECT_GT(fit.heldout_values, 0);
}

// At 9 Hz a 50 Hz grid's third harmonic (150 Hz) lands on 3 Hz, where 60 Hz's fundamental lands
// too, and 60 Hz's third harmonic (180 Hz) lands on 0 Hz; 50 Hz has none there. The lines are the
// 50 Hz mains' (its fundamental on 4 Hz is the stronger), so no session's constant joins them.
TEST(MainsFamilySearch, OnlyTheLinesOwnMainsPutsAHarmonicOnZeroHertz) {
  const SyntheticBench bench(9.0);
  const std::vector<double>& t = bench.series().t_s;
  const std::vector<double> gap =
      with_tones(white_noise(t.size(), 0.02, 15), t, {{50.0, 0.1}, {150.0, 0.05}});
  MainsFamily mains;
  mains.search(bench.part(), gap);
  ASSERT_EQ(mains.lines(), 2u) << ::testing::PrintToString(mains.calibration_lines_hz());
  EXPECT_TRUE(has_line_near(mains.calibration_lines_hz(), 4.0, 0.006));
  EXPECT_TRUE(has_line_near(mains.calibration_lines_hz(), 3.0, 0.006));
  EXPECT_EQ(mains.dc_harmonic_hz(), 0.0);
  const FreeShapeFit fit = mains.fit({bench.part(), bench.part(), gap, gap, false});
  EXPECT_EQ(fit.params.at("mains_hz"), 50.0);
  EXPECT_EQ(fit.params.count("dc_harmonic_hz"), 0u);
}

// A logger that drops one row in 50 at 100 Hz: the rate is the clock's (its median step), not
// the rows over the duration (98 Hz, where 60 Hz would alias to 38 Hz, out of the search's reach
// of the line at 40 Hz).
TEST(MainsFamilySearch, RowsTheLoggerDroppedDoNotMoveTheAliases) {
  const SyntheticBench bench(100.0, 300.0, 0.0, 50);
  const std::vector<double>& t = bench.series().t_s;
  const std::vector<double> gap = with_tones(white_noise(t.size(), 0.02, 16), t, {{60.0, 0.05}});
  MainsFamily mains;
  mains.search(bench.part(), gap);
  ASSERT_EQ(mains.lines(), 1u) << ::testing::PrintToString(mains.calibration_lines_hz());
  EXPECT_TRUE(has_line_near(mains.calibration_lines_hz(), 40.0, 0.006));
}

TEST(MainsFamilySearch, NothingOnPureNoise) {
  const SyntheticBench bench;
  const std::vector<double> gap = white_noise(bench.size(), 0.02, 14);
  MainsFamily mains;
  mains.search(bench.part(), gap);
  EXPECT_TRUE(mains.empty());
  EXPECT_FALSE(mains.lines_are_motion());
  const FreeShapeFit fit = mains.fit({bench.part(), bench.part(), gap, gap, false});
  EXPECT_EQ(fit.cal_voltage_v, std::vector<double>(gap.size(), 0.0));
  EXPECT_EQ(fit.description, "no line at an alias of the mains");
}

// Mount motion on the alias (0.03 mm through the sensor's sensitivity) against cable pickup of
// the same RMS: only the motion's power follows (dV/dd)^2 from window to window.
TEST(MainsLineFinding, LinesWhosePowerFollowsTheSensitivityAreMotion) {
  const SyntheticBench bench;
  const std::vector<double>& t = bench.series().t_s;
  const std::vector<double>& s = bench.replay().sensitivity_v_per_mm();
  double s2 = 0.0;
  for (double v : s) s2 += v * v / static_cast<double>(s.size());
  std::vector<double> motion = white_noise(t.size(), 0.01, 15);
  std::vector<double> pickup = motion;
  for (std::size_t i = 0; i < t.size(); ++i) {
    const double wave = std::sin(2.0 * std::numbers::pi * 2.0 * t[i]);
    motion[i] += 0.03 * s[i] * wave;
    pickup[i] += 0.03 * std::sqrt(s2) * wave;
  }
  EXPECT_EQ(line_source({{bench.part(), motion}}, {2.0}).source, LineSource::kMotion);
  EXPECT_EQ(line_source({{bench.part(), pickup}}, {2.0}).source, LineSource::kPickup);
  MainsFamily mains;
  mains.search(bench.part(), motion);
  EXPECT_TRUE(mains.empty());
  EXPECT_TRUE(mains.lines_are_motion());
}

}  // namespace
}  // namespace flange::diagnose::free_shapes
