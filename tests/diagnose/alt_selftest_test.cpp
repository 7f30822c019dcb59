// SPDX-License-Identifier: MIT
// `flange diagnose --selftest --reality alt`: findings map to classes (the sign of a lag or a
// skew says which channel is late), the scoring counts what it says against the pair's truth,
// and the command runs blind, prints its seed and writes a pair with its truth sidecar.
#include "alt_selftest.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <tuple>

#include "criteria.h"
#include "diagnosis_detail.h"
#include "finding_class.h"
#include "flange_in_process.h"
#include "test_files.h"
#include "twin_file.h"
#include "verdict_reasons.h"

namespace flange::diagnose {
namespace {

using alt_reality::AltPairKind;
using alt_reality::AltPairSpec;

EffectFinding finding(const std::string& name, std::map<std::string, double> params = {}) {
  EffectFinding f;
  f.name = name;
  f.params = std::move(params);
  return f;
}

TEST(AltSelftest, FindingsMapToClassesWithTheLateChannel) {
  EXPECT_EQ(class_of_finding(finding("temp_offset_drift")), "temperature_offset");
  EXPECT_EQ(class_of_finding(finding("thermal_lag", {{"tau_s", 300}})), "sensor_thermal_lag");
  EXPECT_EQ(class_of_finding(finding("thermal_lag", {{"tau_s", -300}})), "temperature_reading_lag");
  EXPECT_EQ(class_of_finding(finding("channel_skew", {{"skew_s", -3}})), "channel_skew");
  EXPECT_EQ(class_of_finding(finding("channel_skew", {{"skew_s", 3}})), "temperature_reading_lag");
  EXPECT_EQ(class_of_finding(finding("adc_quantization")), "quantisation");
  EXPECT_EQ(class_of_finding(finding("vibration")), "mount_vibration");
  EXPECT_EQ(class_of_finding(finding("something_else")), "");
}

AltPairSpec spec_with(AltPairKind kind, std::vector<std::string> classes, double noise_v) {
  AltPairSpec spec;
  spec.kind = kind;
  for (const std::string& c : classes) spec.truth.push_back({{c, "any", {}, ""}, 0.1});
  spec.fit.noise_v = spec.heldout.noise_v = noise_v;
  return spec;
}

TEST(AltSelftest, ScoringCountsTopNearestAndTheGapAboveTheTrueNoise) {
  const AltPairSpec pair =
      spec_with(AltPairKind::kDouble, {"sensor_thermal_lag", "mount_vibration"}, 0.03);
  Diagnosis d;
  d.status = Status::kExplained;
  d.effects = {finding("thermal_lag", {{"tau_s", 500}}), finding("temp_gain_drift")};
  d.heldout_rms_before = 0.05;
  d.heldout_rms_after = 0.03;
  const AltScore s = score_alt_pair(pair, d, {});
  EXPECT_TRUE(s.top_correct);
  EXPECT_FALSE(s.all_found);  // the vibration was not named
  EXPECT_EQ(s.spurious, 1);   // temperature_gain
  EXPECT_FALSE(s.bias_type);
  EXPECT_NEAR(s.shrink_pct, 40.0, 1e-9);
  EXPECT_NEAR(s.excess_shrink_pct, 100.0, 1e-9);  // what is left is the true noise

  Diagnosis unexplained = d;
  unexplained.status = Status::kUnexplained;
  unexplained.effects.clear();
  const AltScore u = score_alt_pair(pair, unexplained, {finding("thermal_lag", {{"tau_s", -50}})});
  EXPECT_TRUE(u.claimed.empty());
  EXPECT_FALSE(u.top_correct);
  EXPECT_EQ(u.nearest, "temperature_reading_lag");
  EXPECT_FALSE(u.nearest_correct);  // the sensor lagged, not the reading
  Diagnosis with_nearest = unexplained;
  with_nearest.nearest = finding("thermal_lag", {{"tau_s", 400}});
  with_nearest.nearest->shrink_pct = 35.0;
  const AltScore w = score_alt_pair(pair, with_nearest, {});
  EXPECT_EQ(w.nearest, "sensor_thermal_lag");  // the diagnosis's own nearest effect
  EXPECT_TRUE(w.nearest_correct);
  EXPECT_EQ(w.nearest_shrink_pct, 35.0);

  Diagnosis none;
  none.status = Status::kNone;
  const AltScore n = score_alt_pair(spec_with(AltPairKind::kNull, {}, 0.05), none, {});
  EXPECT_TRUE(n.verdict_correct);
  std::vector<AltPairResult> results(3);
  results[0].spec = pair;
  results[0].diagnosis = d;
  results[0].score = s;
  results[1].spec = pair;
  results[1].diagnosis = unexplained;
  results[1].score = u;
  results[2].spec = spec_with(AltPairKind::kNull, {}, 0.05);
  results[2].diagnosis = none;
  results[2].score = n;
  const AltSummary summary = summarise_alt_selftest(results);
  EXPECT_EQ(summary.in_library, 2);
  EXPECT_EQ(summary.top_correct, 1);
  EXPECT_EQ(summary.unexplained_in_library, 1);
  EXPECT_EQ(summary.null_none, 1);
  EXPECT_FALSE(summary.top_aim_met);  // 1 of 2
  EXPECT_TRUE(summary.none_aim_met);
  for (const AltClassRow& row : summary.classes) {
    if (row.name == "sensor_thermal_lag") {
      EXPECT_EQ(row.pairs, 2);
      EXPECT_EQ(row.top_correct, 1);
      EXPECT_EQ(row.named, 1);
    }
  }
}

TEST(AltSelftestCommand, RunsBlindAndPrintsItsSeedAndTheTableByClass) {
  const testing::FlangeOutcome o = testing::run_flange_captured(
      {"diagnose", "--selftest", "--reality", "alt", "--pairs", "2", "--seed", "101", "--duration",
       "900", "--bootstrap", "20", "--jobs", "2"});
  EXPECT_TRUE(o.status == 0 || o.status == 1) << o.err;  // 1: an aim missed, not an error
  EXPECT_NE(o.out.find("--reality alt: 2 pairs, seed 101"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("| sensor_thermal_lag |"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("seed 101: aims"), std::string::npos) << o.out;
}

TEST(AltSelftestCommand, OnePairWritesItsSessionsAndItsTruth) {
  const auto dir = testing::fresh_test_dir("alt_selftest_pair");
  const testing::FlangeOutcome o = testing::run_flange_captured(
      {"diagnose", "--selftest", "--reality", "alt", "--case", "8", "--seed", "101", "--duration",
       "900", "--bootstrap", "20", "--out", dir.string()});
  EXPECT_TRUE(o.status == 0 || o.status == 1) << o.err;
  for (const char* file : {"pair_8_fit.csv", "pair_8_heldout.csv", "pair_8_truth.json",
                           "selftest.json", "selftest.md"}) {
    EXPECT_TRUE(std::filesystem::exists(dir / file)) << file;
  }
  std::ifstream in(dir / "selftest.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j["reality"], "alt");
  ASSERT_EQ(j["pairs"].size(), 1u);
  EXPECT_EQ(j["pairs"][0]["kind"], "null");
  // The sessions diagnose on their own as a user would run them, with the start times and the
  // bootstrap the printed command gives (the blind run's bootstrap seed is the seed plus the
  // pair), to the same verdict.
  const std::string same = "  the same diagnosis: flange diagnose --real ";
  const std::size_t line = o.out.find(same);
  ASSERT_NE(line, std::string::npos) << o.out;
  std::istringstream words(o.out.substr(line, o.out.find('\n', line) - line));
  std::map<std::string, std::string> option;
  for (std::string word, previous; words >> word; previous = word) option[previous] = word;
  EXPECT_EQ(option["--real"], (dir / "pair_8_fit.csv").string());
  EXPECT_EQ(option["--holdout"], (dir / "pair_8_heldout.csv").string());
  EXPECT_EQ(option["--seed"], "109");
  EXPECT_EQ(option["--bootstrap"], "20");
  const testing::FlangeOutcome again = testing::run_flange_captured(
      {"diagnose", "--real", option["--real"], "--holdout", option["--holdout"], "--real-start",
       option["--real-start"], "--holdout-start", option["--holdout-start"], "--bootstrap",
       option["--bootstrap"], "--seed", option["--seed"], "--out", (dir / "diag").string()});
  EXPECT_EQ(again.status, 0) << again.err;
  EXPECT_EQ(again.out.rfind("verdict: " + j["pairs"][0]["verdict"].get<std::string>(), 0), 0u)
      << again.out;
}

// Pair `pair` of the alternative reality's seed `seed` (40 pairs a seed), run on its own.
AltPairResult development_pair(std::uint64_t seed, int pair) {
  SelftestOptions options;
  options.cases = 40;
  options.only_case = pair;
  options.seed = seed;
  options.jobs = 1;
  const std::vector<AltPairResult> results = run_alt_selftest(options);
  EXPECT_EQ(results.size(), 1u);
  return results.front();
}

// Pair `pair` of `seed` is explained by `effect` alone, the right class.
void expect_explained_by_one_effect(std::uint64_t seed, int pair, const std::string& effect) {
  const AltPairResult r = development_pair(seed, pair);
  ASSERT_EQ(r.diagnosis.status, Status::kExplained);
  ASSERT_EQ(r.diagnosis.effects.size(), 1u);
  EXPECT_EQ(r.diagnosis.effects[0].name, effect);
  EXPECT_TRUE(r.score.top_correct);
}

// Pair `pair` of `seed` is an outside pair, and nothing is claimed on it.
void expect_unclaimed_outside_pair(std::uint64_t seed, int pair) {
  const AltPairResult r = development_pair(seed, pair);
  ASSERT_EQ(r.spec.kind, AltPairKind::kOutside);
  EXPECT_EQ(r.diagnosis.status, Status::kUnexplained);
  EXPECT_TRUE(r.diagnosis.effects.empty());
}

// Seed 413, pair 2: a log-time ageing across sessions two days apart. The greedy rounds take a
// static nonlinearity first for the calibration part's offset, then the ageing takes the held-out
// gap; with the ageing in, the nonlinearity is not needed and is taken out.
TEST(AltSelftest, APickThatTheLaterPicksMakeUnneededIsTakenOut) {
  expect_explained_by_one_effect(413, 2, "ageing_drift");
}

// Two pairs that the library's formulas split between two classes, the wrong one first: seed
// 447, pair 13, a temperature gain about a mid-range pivot (the library's nonlinearity, then its
// temperature gain), and seed 448, pair 32, a nonlinearity exponential in the voltage (a
// temperature gain, then the nonlinearity and an ageing). One free-shape class leaves as little,
// so it is named alone. The second lowers the top of the range and stays put with temperature,
// as a compression with a fixed knee does: one curve named as a compression, alike the
// nonlinearity (identify/fixed_knees.h).
TEST(AltSelftest, OneClassOfAnotherShapeIsPreferredToTwoLibraryClasses) {
  expect_explained_by_one_effect(447, 13, "temp_gain_drift");
  const AltPairResult r = development_pair(448, 32);
  ASSERT_EQ(r.diagnosis.status, Status::kExplained);
  ASSERT_EQ(r.diagnosis.effects.size(), 1u);
  EXPECT_EQ(r.diagnosis.effects[0].name, "range_compression");
  EXPECT_EQ(r.diagnosis.effects[0].indistinguishable_from, std::vector<std::string>{"nonlinearity"});
  EXPECT_TRUE(r.score.top_among_indistinguishable);
}

// Pairs with a late thermocouple beside a class of the temperature: seed 444, pair 7, a sheathed
// reading lag with a saturating temperature offset, and seed 445, pair 7, a reading lag with a
// dead time beside a range compression with a linear law above a knee that falls along a
// parabola. Their thermocouples read with 0.05-0.1 degC of noise, which a plain inversion of the
// lag would carry into the coil's temperature multiplied by tau / dt; and the compression's shape
// is not the library's, so its free shape is fitted once the lag is in (give_pick_a_free_shape).
// Both classes are named, the lag as a reading lag.
TEST(AltSelftest, AClassBehindALateThermocoupleIsNamedWithTheLag) {
  for (const auto& [seed, pair] : {std::pair<std::uint64_t, int>{444, 7}, {445, 7}}) {
    const AltPairResult r = development_pair(seed, pair);
    EXPECT_EQ(r.diagnosis.status, Status::kExplained) << seed << "/" << pair;
    EXPECT_TRUE(r.score.top_correct) << seed << "/" << pair;
    EXPECT_TRUE(r.score.all_found) << seed << "/" << pair;
    const auto lag = std::find_if(r.diagnosis.effects.begin(), r.diagnosis.effects.end(),
                                  [](const EffectFinding& f) { return f.name == "thermal_lag"; });
    ASSERT_NE(lag, r.diagnosis.effects.end()) << seed << "/" << pair;
    EXPECT_EQ(class_of_finding(*lag), "temperature_reading_lag") << seed << "/" << pair;
  }
}

// Seed 449, pair 11: a temperature gain about a mid-range pivot at 4.5 times the noise. The
// library's formulas take a nonlinearity, a temperature gain and a temperature offset, which with
// free shapes of their own leave 1.02 times the noise; the free pass's temperature gain and
// reading lag leave 1.09 times. Both leave the noise, so the fewer classes are named, the gain
// first.
TEST(AltSelftest, FewerClassesAreNamedWhereBothPassesLeaveTheNoise) {
  const AltPairResult r = development_pair(449, 11);
  ASSERT_EQ(r.diagnosis.status, Status::kExplained);
  ASSERT_FALSE(r.diagnosis.effects.empty());
  EXPECT_EQ(r.diagnosis.effects[0].name, "temp_gain_drift");
  EXPECT_LE(r.diagnosis.effects.size(), 2u);
  EXPECT_TRUE(r.score.top_correct);
}

// Seed 447, pair 17: a log-time ageing with a sensor's thermal lag, both named. Each pick left
// earns its place in the final fit: taking it out costs at least criteria::kRemovalMargin of the
// noise variance.
TEST(AltSelftest, EveryPickLeftIsNeededByTheFinalFit) {
  const AltPairResult r = development_pair(447, 17);
  const std::vector<EffectFinding>& effects = r.diagnosis.effects;
  ASSERT_GE(effects.size(), 2u);
  const double now = r.diagnosis.heldout_rms_after;
  const double least_gain =
      criteria::kRemovalMargin * r.diagnosis.noise_std_v * r.diagnosis.noise_std_v;
  for (std::size_t i = 0; i < effects.size(); ++i) {
    EXPECT_GE(std::pow(effects[i].heldout_rms_without, 2) - now * now, least_gain)
        << effects[i].name;
    // The figures are the final fit's, chained in the listed order.
    if (i + 1 < effects.size()) {
      EXPECT_DOUBLE_EQ(effects[i + 1].heldout_rms_before, effects[i].heldout_rms_after);
    }
  }
  EXPECT_DOUBLE_EQ(effects.back().heldout_rms_after, now);
}

// Pair `pair` of `seed` is explained with `effect` first, the right class, though more
// than `left_over_noise` times the noise is left over the held-out session (beyond the
// calibration's ranges).
void expect_explained_where_the_calibration_reaches(std::uint64_t seed, int pair,
                                                    const std::string& effect,
                                                    double left_over_noise) {
  const AltPairResult r = development_pair(seed, pair);
  ASSERT_EQ(r.diagnosis.status, Status::kExplained);
  ASSERT_FALSE(r.diagnosis.effects.empty());
  EXPECT_EQ(r.diagnosis.effects[0].name, effect);
  EXPECT_TRUE(r.score.top_correct);
  EXPECT_GT(r.diagnosis.heldout_rms_after, left_over_noise * r.diagnosis.noise_std_v);
}

// Seed 101, pair 24: a range compression, weak where the calibration session went (up to
// 57 C, 8.8 mm), strong where the held-out one went on to (75 C, 9.3 mm). Within the calibration's
// ranges the fitted compression leaves the noise; beyond them its continued curve leaves 5 times
// the noise. The class is named, as explained where the calibration reaches.
TEST(AltSelftest, AGapExplainedWhereTheCalibrationReachesIsExplained) {
  expect_explained_where_the_calibration_reaches(101, 24, "range_compression", 2.0);
}

// Seed 430, pair 23: a quadratic temperature gain whose held-out session heats to 93 C, the
// calibration's to 70 C, so only 45 % of its samples lie within the calibration's ranges. There
// what is left is 0.98 times the noise; beyond, the continued curve takes 89 % of the gap above
// the noise (1.42 times the noise left over the session). The less of the session the calibration
// reaches, the more the continued curve must carry, and this one does: explained, though fewer
// than half of the samples lie within.
TEST(AltSelftest, AGapExplainedWhereTheCalibrationReachesCountsWhenTheCurveCarriesBeyond) {
  expect_explained_where_the_calibration_reaches(430, 23, "temp_gain_drift", 1.3);
}

// Seed 425, pair 19: a magnetic hysteresis, outside the library, on a micrometer that reaches
// each clearance from one side. A static nonlinearity matches it within the calibration's ranges,
// but its continued curve takes only 42 % of the gap above the noise where the held-out session
// goes to closer clearances: nothing is claimed.
TEST(AltSelftest, ACurveThatMatchesOnlyWhereTheCalibrationReachesIsNotClaimed) {
  expect_unclaimed_outside_pair(425, 19);
}

// Seed 434, pair 7: a 17.5-times-the-noise rounding converter with a dead-time reading lag at the
// noise level. The converter's rounding follows the voltage, and a temperature offset takes 1 % of
// the noise variance of it: where both parts lie on one grid, a first pick needs 2 % (0.5 %
// elsewhere), and only the quantisation is named.
TEST(AltSelftest, OnAConverterGridAFirstPickNeedsTwoPercent) {
  expect_explained_by_one_effect(434, 7, "adc_quantization");
}

// Seed 436, pair 36: mains at 50 Hz, 0.0175 Hz off and wandering by 0.008 Hz over 19 minutes,
// with a second harmonic. A line of fixed frequency turns against it by up to a third of a cycle
// across a 20 s window and would leave 1.3 times the noise; the held-out windows shorten to 10 or
// 5 s where they fit better, and the mains is named.
TEST(AltSelftest, AWanderingGridIsFollowedWithShorterWindows) {
  expect_explained_by_one_effect(436, 36, "mains_pickup");
}

// Pair `pair` of `seed` diagnosed, then again against the twin.json the first diagnosis wrote
// (through the twin file, as `flange diagnose --twin twin.json` reads it).
struct Rediagnosis {
  DiagnosisResult first, second;
};
Rediagnosis rediagnose_alt_pair(std::uint64_t seed, int pair) {
  const alt_reality::AltPairSpec spec = alt_reality::draw_alt_pair(pair, seed);
  const alt_reality::AltPair recorded = alt_reality::render_alt_pair(spec);
  const RecordingSeries fit = alt_series(recorded.fit, spec.fit, "fit");
  const RecordingSeries heldout = alt_series(recorded.heldout, spec.heldout, "held-out");
  DiagnoseOptions options;
  options.bootstrap_rounds = 20;
  Rediagnosis r;
  r.first = diagnose_in_detail(fit, heldout, options);
  options.twin = sim::twin_from_json(sim::twin_to_json(r.first.improved_twin.twin), "twin.json");
  r.second = diagnose_in_detail(fit, heldout, options);
  return r;
}

bool any_reason_holds(const DiagnosisResult& r, const std::string& phrase) {
  return std::any_of(r.detail.reasons.begin(), r.detail.reasons.end(),
                     [&](const std::string& why) { return why.find(phrase) != std::string::npos; });
}

// The same pair. Lines fitted window by window cannot be replayed on another session: the
// improved twin holds mains pickup as each session's own lines, and the diagnosis against it
// takes each part's own out before the rest.
TEST(AltSelftest, AWanderingGridHeldAsEachSessionsOwnLinesLeavesNone) {
  const Rediagnosis r = rediagnose_alt_pair(436, 36);
  ASSERT_EQ(r.first.diagnosis.status, Status::kExplained);
  ASSERT_EQ(r.first.improved_twin.findings.size(), 1u);
  EXPECT_EQ(r.first.improved_twin.findings[0].held_as, HeldAs::kSessionLines);
  EXPECT_EQ(r.second.diagnosis.status, Status::kNone);
  EXPECT_TRUE(any_reason_holds(r.second, "whose lines are each session's own"));
  // The twin it hands back holds the lines still.
  const std::vector<sim::EffectSettings>& again = r.second.improved_twin.twin.effects;
  EXPECT_TRUE(std::any_of(again.begin(), again.end(), [](const sim::EffectSettings& e) {
    return e.name == "mains_pickup";
  }));
}

// Seed 467, pair 6: a 5-bit converter over 1.2-11.2 V whose codes the twin's converter does not
// reproduce, so its rounding is taken as noise. The improved twin holds it in the white noise and
// names the grid (noise.rounding_lsb_v); against that twin the grid is not named again.
TEST(AltSelftest, AConverterHeldInTheNoiseIsNotNamedAgain) {
  const Rediagnosis r = rediagnose_alt_pair(467, 6);
  ASSERT_EQ(r.first.diagnosis.status, Status::kExplained);
  ASSERT_EQ(r.first.improved_twin.findings.size(), 1u);
  EXPECT_EQ(r.first.improved_twin.findings[0].held_as, HeldAs::kWhiteNoise);
  EXPECT_GT(r.first.improved_twin.twin.noise.rounding_lsb_v, 0.3);
  EXPECT_EQ(r.second.diagnosis.status, Status::kNone);
  EXPECT_EQ(r.second.improved_twin.twin.noise.rounding_lsb_v,
            r.first.improved_twin.twin.noise.rounding_lsb_v);
}

// Seed 470, pair 2: a DAQ whose channel clocks drift apart, the voltage late by a skew that
// grows through each session. The free shape finds the skew's law; the improved twin holds it as
// the library's channel_skew with its drift, and against that twin the pair leaves "none".
TEST(AltSelftest, ADriftingSkewIsHeldByItsLaw) {
  const Rediagnosis r = rediagnose_alt_pair(470, 2);
  ASSERT_EQ(r.first.diagnosis.status, Status::kExplained);
  ASSERT_EQ(r.first.improved_twin.findings.size(), 1u);
  EXPECT_EQ(r.first.improved_twin.findings[0].held_as, HeldAs::kLibraryEffectAndTable);
  const std::vector<sim::EffectSettings>& held = r.first.improved_twin.twin.effects;
  const auto skew = std::find_if(held.begin(), held.end(), [](const sim::EffectSettings& e) {
    return e.name == "channel_skew";
  });
  ASSERT_NE(skew, held.end());
  EXPECT_NE(skew->params.at("drift_s_per_h"), 0.0);
  EXPECT_EQ(r.second.diagnosis.status, Status::kNone);
}

// Seed 468, pair 36: an ageing, explained within the calibration's ranges only (24.9-69.9 C; the
// held-out session reaches 16.5-88.3 C, where its free shape is held at its ends). The improved
// twin's table carries those ranges, and against it the held-out gap within them is at the noise
// while what lies beyond lies beyond the table's fits: "none", saying where the twin continues.
TEST(AltSelftest, AGapExplainedWithinReachIsLeftOnlyBeyondTheTwinsFits) {
  const Rediagnosis r = rediagnose_alt_pair(468, 36);
  ASSERT_EQ(r.first.diagnosis.status, Status::kExplained);
  EXPECT_TRUE(any_reason_holds(r.first, "lie beyond them"));
  const std::vector<sim::EffectSettings>& held = r.first.improved_twin.twin.effects;
  ASSERT_FALSE(held.empty());
  for (const sim::EffectSettings& effect : held) {
    ASSERT_TRUE(effect.fitted_over.has_value()) << effect.name;
    EXPECT_NEAR(effect.fitted_over->temperature_lo_c, 24.9, 0.05);
    EXPECT_NEAR(effect.fitted_over->temperature_hi_c, 69.9, 0.05);
  }
  EXPECT_EQ(r.second.diagnosis.status, Status::kNone);
  EXPECT_TRUE(any_reason_holds(r.second, "beyond the ranges the twin's"));
  EXPECT_TRUE(r.second.diagnosis.effects.empty());
  // The rejected pick asks for no measurement.
  EXPECT_TRUE(r.second.diagnosis.next_measurement.empty());
  // Both verdicts say where they hold.
  EXPECT_EQ(r.first.diagnosis.scope, "where the calibration reaches (24.9-69.9 C, 2.46-9.46 mm)");
  EXPECT_EQ(r.second.diagnosis.scope, r.first.diagnosis.scope);
}

// Seed 470, pair 27: a sheathed reading lag (at the noise) beside a temperature offset. Given
// free shapes in the order the picks were made, the temperature class's shape was fitted behind
// the library's lag, which the lag's own free shape then replaced: an "explained" whose shapes
// follow a temperature no effect of it makes, which its twin could not hold ("not held") and
// re-diagnosis called "unexplained". With the delay's free shape first, what is explained is held.
TEST(AltSelftest, AnExplainedReadingLagBesideATemperatureClassIsHeldByItsTwin) {
  const Rediagnosis r = rediagnose_alt_pair(470, 27);
  for (const HeldFinding& finding : r.first.improved_twin.findings) {
    EXPECT_NE(finding.held_as, HeldAs::kNotHeld) << finding.name << ": " << finding.note;
  }
  if (r.first.diagnosis.status == Status::kExplained) {
    EXPECT_EQ(r.second.diagnosis.status, Status::kNone);
  }
  // The library's lag leaves 1.13 times the noise: the verdict may not call it explained.
  EXPECT_NE(r.first.diagnosis.status, Status::kNone);
}

// Seed 447, pair 35: a log-time ageing, a ln(1 + age / 0.80 d), whose held-out session starts
// 16 h after an hour-long calibration session (start times given). Over that hour the settling
// barely bends, so a straight line carries it too far (it would leave 0.103 V, 1.85 times the
// noise). The calibration part keeps the settlings it does not reject, and the held-out level
// chooses among them (one value fitted there).
TEST(AltSelftest, ASettlingAgeingIsCarriedToALaterSessionByItsLevelThere) {
  const AltPairResult r = development_pair(447, 35);
  ASSERT_EQ(r.diagnosis.status, Status::kExplained);
  ASSERT_EQ(r.diagnosis.effects.size(), 1u);
  EXPECT_EQ(r.diagnosis.effects[0].name, "ageing_drift");
  EXPECT_GT(r.diagnosis.effects[0].params.count("settling_tau_days"), 0u);
  EXPECT_TRUE(r.score.top_correct);
}

// Seed 448, pair 35: 50 Hz mains with odd harmonics at 6 Hz, where the third harmonic (150 Hz)
// lands on 0 Hz: a constant in each session set by the mains' phase at its start, 0.33 V here.
// The lines at 2 Hz alone leave the held-out session's own constant (0.118 V, 1.34 times the
// noise), so each session's constant joins the lines.
TEST(AltSelftest, AMainsHarmonicOnZeroHertzIsAConstantOfEachSession) {
  const AltPairResult r = development_pair(448, 35);
  ASSERT_EQ(r.diagnosis.status, Status::kExplained);
  ASSERT_EQ(r.diagnosis.effects.size(), 1u);
  EXPECT_EQ(r.diagnosis.effects[0].name, "mains_pickup");
  EXPECT_EQ(r.diagnosis.effects[0].params.at("dc_harmonic_hz"), 150.0);
}

// Seed 452, pair 14: a 6-bit rounding converter over +-10.24 V (LSB 0.32 V) with 0.013 V of
// analog noise, on a sawtooth staircase. What the grid leaves over the session is within the
// noise, but a dwell on a code boundary leaves 0.12 V in one 64th of it, more than twice the
// 0.054 V the grid leaves on average. On a code boundary the signal flips between two codes at
// random, so a window may hold up to LSB / sqrt(2): such a window is not a miss.
TEST(AltSelftest, ADwellOnACodeBoundaryIsNotAMissOnACoarseGrid) {
  expect_explained_by_one_effect(452, 14, "adc_quantization");
}

// Seed 450, pair 27: a clearance ripple of 3.9 mm period behind a 4.8 s delay of the voltage
// channel, on a motorised sweep. A free curve of clearance added after the chain would follow the
// recorded clearance rather than the one the late voltage was made at, and smear the ripple
// wherever the micrometer moves (1.3 times the noise left beside the skew); the free shapes see
// the inputs the voltage was made at.
TEST(AltSelftest, ARippleBehindALateVoltageChannelIsACurveOfTheClearanceItSaw) {
  const AltPairResult r = development_pair(450, 27);
  ASSERT_EQ(r.diagnosis.status, Status::kExplained);
  EXPECT_TRUE(r.score.top_correct);
  EXPECT_TRUE(r.score.all_found);
}

// Seed 453, pair 4 and seed 454, pair 3: clearance ripples of 2.53 and 2.67 mm period, whose
// held-out sessions go 1.1 mm (above) and 0.5-0.6 mm (at both ends) beyond the calibration's
// clearance range. A curve of the clearance held or continued along a line there would leave 2.0
// and 1.3 times the noise; the periodic family repeats the ripple and finds its period.
TEST(AltSelftest, AClearanceRippleRepeatsBeyondTheCalibrationsRange) {
  for (const auto& [seed, pair, period_mm] :
       {std::tuple<std::uint64_t, int, double>{453, 4, 2.528}, {454, 3, 2.667}}) {
    const AltPairResult r = development_pair(seed, pair);
    ASSERT_EQ(r.diagnosis.status, Status::kExplained) << seed << "/" << pair;
    ASSERT_EQ(r.diagnosis.effects.size(), 1u) << seed << "/" << pair;
    EXPECT_EQ(r.diagnosis.effects[0].name, "nonlinearity") << seed << "/" << pair;
    EXPECT_NEAR(r.diagnosis.effects[0].params.at("ripple_period_mm"), period_mm, 0.03)
        << seed << "/" << pair;
  }
}

// Seed 440, pair 1: a narrow mount resonance at 26.6 Hz sampled at 9 Hz, which the sampling
// aliases to within about 1.2 Hz of 0 Hz. Levels taken about a moving mean of 49 samples would see
// only 60 % of the motion's variance (and leave 1.13 times what the noise plus that motion
// allows); over the whole session, with only the noise left beside the motion, the motion's
// variance is all there.
TEST(AltSelftest, MotionAliasedNearZeroHertzIsCountedOverTheSession) {
  const AltPairResult r = development_pair(440, 1);
  ASSERT_EQ(r.diagnosis.status, Status::kExplained);
  ASSERT_FALSE(r.diagnosis.effects.empty());
  EXPECT_EQ(r.diagnosis.effects[0].name, "vibration");
  EXPECT_TRUE(r.score.top_correct);
}

// Seed 436, pair 39: a magnetic hysteresis, outside the library, under mount motion. What the
// picks leave of it grows faster than (dV/dd)^2, so regressed over the session it would pass for
// more motion if the slope alone were read; the regression's intercept, below zero, says it is
// not the noise beside a motion.
TEST(AltSelftest, AHysteresisLeftByThePicksDoesNotPassForMotion) {
  expect_unclaimed_outside_pair(436, 39);
}

// Seed 443, pair 19: a magnetic hysteresis on a sawtooth staircase, outside the library. What a
// nonlinearity leaves of it changes where the clearance moves, and with the sensitivity there it
// could pass for mount motion, whose noise would then cover the rest. Taken at rest, the gap
// shows no motion.
TEST(AltSelftest, ABiasThatChangesWithTheMovesDoesNotPassForMotion) {
  expect_unclaimed_outside_pair(443, 19);
}

TEST(AltSelftestCommand, AnUnknownRealityIsABadArgument) {
  const testing::FlangeOutcome o =
      testing::run_flange_captured({"diagnose", "--selftest", "--reality", "mars"});
  EXPECT_EQ(o.status, 2) << o.err;
  EXPECT_NE(o.err.find("--reality"), std::string::npos) << o.err;
}

}  // namespace
}  // namespace flange::diagnose
