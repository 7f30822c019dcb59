// SPDX-License-Identifier: MIT
// The third reality (diagnose/third_reality/): its sensor is eq. 3.14, its shapes are drawn (a
// monotone smooth function stays monotone, a kernel settles, a band shows where the sampling
// folds it), its pairs are reproducible and hold every class alone and in twos and threes, every
// effect adds 1.2-2 times the noise, its rates span 6-100 Hz and its logger drops and jitters,
// and the truth goes to a sidecar beside the recordings.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>

#include "band_motion.h"
#include "lag_kernel.h"
#include "recording_series.h"
#include "test_files.h"
#include "third_classes.h"
#include "third_pairs.h"
#include "third_sensor.h"
#include "third_truth.h"

namespace flange::third_reality {
namespace {

// Every test draws from these pairs: 110 of seed 5, sessions capped at 600 s.
const std::vector<ThirdPairSpec>& hundred_and_ten_pairs() {
  static const std::vector<ThirdPairSpec> pairs = [] {
    std::vector<ThirdPairSpec> drawn;
    for (int i = 1; i <= 110; ++i) drawn.push_back(draw_third_pair(i, 5, 600.0));
    return drawn;
  }();
  return pairs;
}

TEST(ThirdReality, SensorIsEq314) {
  for (double t = 0.0; t <= 100.0; t += 12.5) {
    for (double d = 1.5; d <= 9.0; d += 0.37) {
      const double v = nominal_voltage(d, t);
      EXPECT_NEAR(1.16 + 0.3672 * v - 0.0036 * t + 0.05812 * v * v + 0.0006618 * v * t, d, 1e-9);
    }
  }
  EXPECT_EQ(nominal_voltage(30.0, 20.0), kRailHighV);
}

TEST(ThirdReality, DrawnShapesAreSmoothMonotoneWhenAskedAndKernelsSettle) {
  ThirdRandom random(3);
  for (int i = 0; i < 50; ++i) {
    const SmoothFunction f = draw_smooth_function(true, random);
    const double direction = f(1.0) > f(0.0) ? 1.0 : -1.0;
    for (double u = 0.0; u < 1.0; u += 0.01) EXPECT_GE(direction * (f(u + 0.01) - f(u)), -1e-12);
    EXPECT_NEAR(std::abs(f(1.0) - f(0.0)), 2.0, 1e-9);
    const LagKernel kernel = draw_lag_kernel(1 + i % 3, 30.0, 900.0, 60.0, random);
    ASSERT_EQ(static_cast<int>(kernel.paths.size()), 1 + i % 3);
    std::vector<double> instants;
    for (double t = 0.0; t < 20000.0; t += 7.0) instants.push_back(t);
    const std::vector<double> step = apply_lag_kernel(
        kernel, [](double t) { return t < 100.0 ? 20.0 : 80.0; }, instants);
    EXPECT_NEAR(step.front(), 20.0, 1e-9);
    EXPECT_NEAR(step.back(), 80.0, 1e-6);
  }
  // A band above the Nyquist frequency of a 6-12.5 Hz logger folds into [0.4, fs/2 - 0.4].
  for (double fs : {6.0, 7.0, 8.0, 9.0, 10.0, 12.5}) {
    const BandMotion motion = draw_band_motion(fs, random);
    EXPECT_GT(motion.centre_hz, fs / 2.0);
    EXPECT_TRUE(shows_as_a_line(motion.centre_hz, fs, 0.4));
  }
}

TEST(ThirdReality, PairsAreDeterministicPerSeed) {
  for (int i : {1, 5, 7, 9}) {
    const ThirdPairSpec a = draw_third_pair(i, 11, 600.0), b = draw_third_pair(i, 11, 600.0);
    ASSERT_EQ(a.truth.size(), b.truth.size());
    for (std::size_t k = 0; k < a.truth.size(); ++k) {
      EXPECT_EQ(a.truth[k].draw.params, b.truth[k].draw.params) << i;
    }
    const ThirdPair ra = render_third_pair(a), rb = render_third_pair(b);
    EXPECT_EQ(ra.fit.voltage_v, rb.fit.voltage_v) << i;
    EXPECT_EQ(ra.heldout.t_s, rb.heldout.t_s) << i;
    EXPECT_NE(a.fit.noise_seed, draw_third_pair(i, 12, 600.0).fit.noise_seed) << i;
  }
}

TEST(ThirdReality, EveryClassIsDrawnAloneAndInTwosAndThrees) {
  std::map<std::string, int> kinds, alone, together;
  std::map<std::size_t, int> multiple_sizes;
  for (const ThirdPairSpec& spec : hundred_and_ten_pairs()) {
    kinds[third_pair_kind_name(spec.kind)]++;
    if (spec.kind == ThirdPairKind::kMulti) multiple_sizes[spec.truth.size()]++;
    for (const ThirdTruthEffect& e : spec.truth) {
      (spec.kind == ThirdPairKind::kMulti ? together : alone)[e.draw.class_name]++;
    }
    const int setters =
        static_cast<int>(std::count_if(spec.truth.begin(), spec.truth.end(), [](const auto& e) {
          return third_class(e.draw.class_name).sets_noise;
        }));
    EXPECT_LE(setters, 1) << spec.index;
  }
  EXPECT_EQ(kinds["single"], 44);
  EXPECT_EQ(kinds["multiple"], 33);
  EXPECT_EQ(kinds["null"], 22);
  EXPECT_EQ(kinds["outside"], 11);
  EXPECT_EQ(multiple_sizes[2], 22);
  EXPECT_EQ(multiple_sizes[3], 11);
  for (const ThirdClass& c : third_classes()) {
    EXPECT_GE(alone[c.name], 4) << c.name;
    EXPECT_GE(together[c.name], 1) << c.name;
  }
  EXPECT_EQ(alone["outside"], 11);
}

TEST(ThirdReality, EveryEffectAddsOnePointTwoToTwoTimesTheNoise) {
  int effects = 0;
  for (const ThirdPairSpec& spec : hundred_and_ten_pairs()) {
    EXPECT_GE(spec.fit.noise_v, 0.002 - 1e-12);
    EXPECT_LE(spec.fit.noise_v, 0.1 + 1e-12);
    for (const ThirdTruthEffect& e : spec.truth) {
      ++effects;
      const double size = e.rms_v / spec.fit.noise_v;
      EXPECT_GE(size, kLeastSize * 0.98)
          << spec.index << " " << e.draw.class_name << "/" << e.draw.shape;
      EXPECT_LE(size, kMostSize * 1.02)
          << spec.index << " " << e.draw.class_name << "/" << e.draw.shape;
    }
  }
  EXPECT_GT(effects, 120);
}

TEST(ThirdReality, RatesSpanSixToAHundredHertzAndTheLoggerDropsAndJitters) {
  std::set<double> rates;
  for (const ThirdPairSpec& spec : hundred_and_ten_pairs()) rates.insert(spec.fit.fs_hz);
  EXPECT_EQ(*rates.begin(), 6.0);
  EXPECT_EQ(*rates.rbegin(), 100.0);
  EXPECT_GE(rates.size(), 8u);
  for (int i : {1, 2, 3}) {
    const ThirdPairSpec spec = draw_third_pair(i, 7, 900.0);
    const ThirdRecording fit = render_third_pair(spec).fit;
    const auto planned =
        static_cast<std::size_t>(std::floor(spec.fit.duration_s * spec.fit.fs_hz)) + 1;
    EXPECT_GT(fit.dropped, 0u) << i;
    EXPECT_EQ(fit.size() + fit.dropped, planned) << i;
    std::set<double> steps;
    for (std::size_t k = 1; k < fit.size(); ++k) {
      ASSERT_GT(fit.t_s[k], fit.t_s[k - 1]) << i << " row " << k;
      steps.insert(std::round((fit.t_s[k] - fit.t_s[k - 1]) * 1e6));
    }
    EXPECT_GT(steps.size(), 3u) << i;  // jittered and with gaps, not one step
    EXPECT_EQ(fit.t_s.front(), 0.0);
  }
}

// Every shape of every class, alone on a null pair's session, changes what an ideal twin sees.
TEST(ThirdReality, EveryShapeOfEveryClassChangesWhatAnIdealTwinSees) {
  ThirdPairSpec spec = draw_third_pair(8, 3, 900.0);
  ASSERT_EQ(spec.kind, ThirdPairKind::kNull);
  spec.fit.fs_hz = 7.0;  // where the mains and a band both show
  const std::vector<double> base = ideal_twin_gap(render_session(spec.fit, {}, false));
  std::vector<ThirdClass> classes = third_classes();
  classes.push_back(third_class("outside"));
  ThirdRandom random(17);
  DrawContext context;
  context.fs_hz = 7.0;
  context.age_lo_s = spec.fit.start_age_s;
  context.age_hi_s = spec.fit.start_age_s + 86400.0;
  for (const ThirdClass& c : classes) {
    ASSERT_GE(c.shapes.size(), 2u) << c.name;
    for (const std::string& shape : c.shapes) {
      const EffectDraw draw = c.draw(shape, context, random);
      const std::vector<double> with = ideal_twin_gap(render_session(spec.fit, {draw}, false));
      double sum = 0.0;
      for (std::size_t k = 0; k < base.size(); ++k) sum += std::pow(with[k] - base[k], 2);
      EXPECT_GT(std::sqrt(sum / static_cast<double>(base.size())), 1e-3) << c.name << "/" << shape;
    }
  }
}

TEST(ThirdReality, TheTruthGoesToASidecarBesideTheRecordings) {
  const auto dir = testing::fresh_test_dir("third_reality_pair");
  const ThirdPairSpec spec = draw_third_pair(7, 2, 600.0);  // three classes
  const ThirdPair pair = render_third_pair(spec);
  const auto paths = write_third_pair(dir, spec, pair);
  ASSERT_EQ(paths.size(), 3u);
  const diagnose::RecordingSeries fit = diagnose::read_recording_series(paths[0].string());
  ASSERT_EQ(fit.size(), pair.fit.size());
  for (std::size_t i = 0; i < fit.size(); i += 97) {
    EXPECT_EQ(fit.voltage_v[i], pair.fit.voltage_v[i]) << i;
    EXPECT_EQ(fit.t_s[i], pair.fit.t_s[i]) << i;
  }
  std::ifstream in(paths[2]);
  const nlohmann::json truth = nlohmann::json::parse(in);
  EXPECT_EQ(truth["kind"], "multiple");
  EXPECT_EQ(truth["truth"].size(), 3u);
  EXPECT_TRUE(truth["fit_session"].contains("logger"));
}

}  // namespace
}  // namespace flange::third_reality
