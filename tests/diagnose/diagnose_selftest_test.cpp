// SPDX-License-Identifier: MIT
// `flange diagnose --selftest`: the cases are drawn reproducibly with every kind present, the
// outside-the-library effects really change the recording, the scoring counts what it says, cases
// on two threads give what each gives alone, and the command line runs a small blind set against
// the aims (CI's small set; bench/ runs 50).
#include "diagnose_selftest.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "cli.h"
#include "diagnosis_detail.h"
#include "recording_series.h"
#include "test_files.h"

namespace flange::diagnose {
namespace {

TEST(DiagnoseSelftest, CasesAreReproducibleAndCycleThroughEveryKind) {
  std::multiset<std::string> kinds;
  std::set<std::string> effects;
  for (int i = 1; i <= 30; ++i) {
    const SelftestCaseSpec a = draw_selftest_case(i, 7);
    const SelftestCaseSpec b = draw_selftest_case(i, 7);
    EXPECT_EQ(a.truth, b.truth) << i;
    EXPECT_EQ(a.noise_seed, b.noise_seed) << i;
    kinds.insert(selftest_kind_name(a.kind));
    for (const auto& e : a.truth) effects.insert(e.name);
    switch (a.kind) {
      case SelftestKind::kSingle:
        EXPECT_EQ(a.truth.size(), 1u);
        break;
      case SelftestKind::kPair:
        ASSERT_EQ(a.truth.size(), 2u);
        EXPECT_NE(a.truth[0].name, a.truth[1].name);
        break;
      case SelftestKind::kNull:
      case SelftestKind::kOutside:
        EXPECT_TRUE(a.truth.empty());
        break;
    }
  }
  EXPECT_EQ(kinds.count("single"), 15u);
  EXPECT_EQ(kinds.count("pair"), 6u);
  EXPECT_EQ(kinds.count("null"), 3u);
  EXPECT_EQ(kinds.count("outside"), 6u);
  EXPECT_GE(effects.size(), 8u);  // 27 draws over 10 effects
  EXPECT_NE(draw_selftest_case(1, 7).noise_seed, draw_selftest_case(1, 8).noise_seed);
}

// Case 8 of every seed is a null case; outside cases are 9 and 10.
SelftestCaseSpec outside_case(const std::string& name) {
  SelftestCaseSpec spec = draw_selftest_case(8, 3);
  spec.kind = SelftestKind::kOutside;
  spec.outside = {name, name == "backlash" ? 0.4 : 0.08, 0.5};
  return spec;
}

TEST(DiagnoseSelftest, OutsideEffectsChangeTheRecordingWhereTheySay) {
  constexpr double kDurationS = 1200;
  const SelftestCaseSpec null_spec = draw_selftest_case(8, 3);
  ASSERT_EQ(null_spec.kind, SelftestKind::kNull);
  const SelftestRecordings null_rec = make_selftest_recordings(null_spec, kDurationS);
  const SelftestRecordings step = make_selftest_recordings(outside_case("gain_step"), kDurationS);
  const SelftestRecordings backlash =
      make_selftest_recordings(outside_case("backlash"), kDurationS);
  ASSERT_EQ(step.calibration.size(), null_rec.calibration.size());
  std::size_t changed_before_step = 0, changed_after_step = 0, backlash_changed = 0;
  for (std::size_t i = 0; i < null_rec.calibration.size(); ++i) {
    // Same noise seed, so the recordings differ only by the effect.
    const bool differs = step.calibration.voltage_v[i] != null_rec.calibration.voltage_v[i];
    (step.calibration.t_s[i] < 0.5 * kDurationS ? changed_before_step : changed_after_step) +=
        differs ? 1 : 0;
    backlash_changed += backlash.calibration.voltage_v[i] != null_rec.calibration.voltage_v[i];
    // The reference column stays the micrometer reading.
    EXPECT_EQ(backlash.calibration.clearance_mm[i], null_rec.calibration.clearance_mm[i]);
  }
  EXPECT_EQ(changed_before_step, 0u);
  EXPECT_GT(changed_after_step, null_rec.calibration.size() / 3);
  EXPECT_GT(backlash_changed, null_rec.calibration.size() / 4);
  // The held-out session is another session, not a copy.
  EXPECT_NE(null_rec.heldout.temp_c.back(), null_rec.calibration.temp_c.back());
}

TEST(DiagnoseSelftest, ScoringCountsTopAllSpuriousAndExcessShrink) {
  SelftestCaseSpec spec;
  spec.kind = SelftestKind::kPair;
  spec.truth = {sim::make_effect_settings("temp_offset_drift", {}, "test"),
                sim::make_effect_settings("vibration", {}, "test")};
  Diagnosis d;
  d.status = Status::kExplained;
  d.effects = {{"temp_offset_drift", {}, 0, 0, 0, 1, false, ""},
               {"channel_skew", {}, 0, 0, 0, 1, false, ""}};
  d.heldout_rms_before = 0.5;
  d.heldout_rms_after = 0.3;
  const SelftestScore s = score_selftest_case(spec, d, 0.3);
  EXPECT_TRUE(s.top_correct);
  EXPECT_FALSE(s.all_found);  // vibration not named
  EXPECT_EQ(s.spurious, 1);   // channel_skew
  EXPECT_FALSE(s.bias_type);  // vibration cannot be subtracted
  EXPECT_NEAR(s.shrink_pct, 40.0, 1e-9);
  EXPECT_NEAR(s.excess_shrink_pct, 100.0, 1e-9);  // what is left is the noise

  SelftestCaseSpec null_spec;
  null_spec.kind = SelftestKind::kNull;
  d.status = Status::kUnexplained;  // partial findings are not claims
  const SelftestScore n = score_selftest_case(null_spec, d, 0.3);
  EXPECT_TRUE(n.claimed.empty());
  EXPECT_FALSE(n.verdict_correct);
  std::vector<SelftestCaseResult> results(2);
  results[0].spec = spec;
  results[0].score = s;
  results[1].spec = null_spec;
  results[1].score = n;
  const SelftestSummary summary = summarise_selftest(results);
  EXPECT_EQ(summary.in_library, 1);
  EXPECT_EQ(summary.top_correct, 1);
  EXPECT_EQ(summary.null_claims, 0);
  EXPECT_EQ(summary.null_none, 0);
  EXPECT_TRUE(summary.top_aim_met);
}

// The twin's self-test case `case_index` of `seed` on its own.
SelftestCaseResult run_case(int seed, int case_index) {
  SelftestOptions options;
  options.seed = static_cast<std::uint64_t>(seed);
  options.only_case = case_index;
  const std::vector<SelftestCaseResult> results = run_selftest(options);
  EXPECT_EQ(results.size(), 1u);
  return results.empty() ? SelftestCaseResult{} : results.front();
}

// ... which must be an outside case with a gain step (the kind the next two tests are about); the
// test stops if it is not.
void run_gain_step_case(int seed, int case_index, SelftestCaseResult& result) {
  result = run_case(seed, case_index);
  ASSERT_EQ(result.spec.kind, SelftestKind::kOutside);
  ASSERT_EQ(result.spec.outside.name, "gain_step");
}

// A -4.7 % gain step at 0.66 of each session (fixture: the twin self-test's seed 4, case 49): the
// sessions are below 38 C almost only after it, so a temperature gain curve takes it and leaves
// 1.10 times the noise over the held-out session, within what "explained" allows there. Around the
// step it leaves more than twice the noise: no effect is claimed, and the temperature gain is named
// as the nearest.
TEST(DiagnoseSelftest, AGainStepThatATemperatureCurveTakesIsNotClaimed) {
  SelftestCaseResult r;
  ASSERT_NO_FATAL_FAILURE(run_gain_step_case(4, 49, r));
  EXPECT_EQ(r.diagnosis.status, Status::kUnexplained);
  EXPECT_TRUE(r.diagnosis.effects.empty());
  EXPECT_LE(r.diagnosis.heldout_rms_after, 1.10 * r.diagnosis.noise_std_v);
  ASSERT_TRUE(r.diagnosis.nearest);
  EXPECT_EQ(r.diagnosis.nearest->name, "temp_gain_drift");
  EXPECT_NE(r.diagnosis.nearest->evidence.find("within"), std::string::npos)
      << r.diagnosis.nearest->evidence;
}

// A -4.1 % gain step at 0.51 of each session (fixture: the twin self-test's seed 8, case 20), whose
// clocks restart at 0 with no start times. An ageing curve with the held-out session placed 75 s
// before the calibration one (overlapping it) would follow the step into both. Two sessions cannot
// overlap in time, so the held-out session may only lie wholly before or after the calibration
// session; then no age curve carries the step across, and nothing is claimed.
TEST(DiagnoseSelftest, AStepAtTheSameTimeInBothSessionsIsNotTakenForAgeing) {
  SelftestCaseResult r;
  ASSERT_NO_FATAL_FAILURE(run_gain_step_case(8, 20, r));
  EXPECT_EQ(r.diagnosis.status, Status::kUnexplained);
  EXPECT_TRUE(r.diagnosis.effects.empty());
  ASSERT_TRUE(r.diagnosis.nearest);
  EXPECT_EQ(r.diagnosis.nearest->name, "temp_gain_drift");
}

// Case `case_index` of `seed` holds `effect` alone, and the diagnosis explains it by that alone.
void expect_explained_by_its_one_effect(int seed, int case_index, const std::string& effect) {
  const SelftestCaseResult r = run_case(seed, case_index);
  ASSERT_EQ(r.spec.truth.size(), 1u);
  ASSERT_EQ(r.spec.truth.front().name, effect);
  EXPECT_EQ(r.diagnosis.status, Status::kExplained);
  ASSERT_EQ(r.diagnosis.effects.size(), 1u);
  EXPECT_EQ(r.diagnosis.effects.front().name, effect);
}

// A 133 s thermal lag at 0.07 V of noise (fixture: the twin self-test's seed 11, case 22): a
// thermal lag takes 0.9 % of the noise variance off the held-out gap, with a bootstrap bound above
// zero. The first pick needs 0.5 % (later ones 2 %), so the lag is named; a first pick held to 2 %
// would name nothing.
TEST(DiagnoseSelftest, AWeakThermalLagIsNamedByTheFirstPicksLeastGain) {
  expect_explained_by_its_one_effect(11, 22, "thermal_lag");
}

// Mount motion of 0.35 mm RMS (fixture: the twin self-test's seed 11, case 1): where the sensor's
// curve bends it moves the mean voltage, which a static nonlinearity takes at 0.6 % of the noise
// variance. Where the motion shows before any pick, a first pick needs 2 %, and the motion is named
// alone.
TEST(DiagnoseSelftest, MountMotionKeepsTheFirstPicksLeastGainAtTwoPercent) {
  expect_explained_by_its_one_effect(11, 1, "vibration");
}

// A temperature-reading lag of 62 s at 0.07 V of noise (fixture: the twin self-test's seed 15, case
// 25): the held-out gap is 1.017 times the noise, no gap, and a thermal lag takes 0.30 % of the
// noise variance off it, above what the candidates gain by chance against the held-out gap
// shifted in time (under 0.2 % here), so the selection picks it. But it takes only 4.5 % of the gap
// above the noise, no better than seven other classes: what a flexible class fitted to a residue
// of the noise also does (criteria::kLeastShareOfNoGapTaken). The verdict says "none" and names
// the lag in its reasons, not as a finding.
TEST(DiagnoseSelftest, AWeakReadingLagWithinTheNoiseIsNamedInTheReasonsNotClaimed) {
  const SelftestCaseResult r = run_case(15, 25);
  ASSERT_EQ(r.spec.truth.size(), 1u);
  ASSERT_EQ(r.spec.truth.front().name, "thermal_lag");
  EXPECT_EQ(r.diagnosis.status, Status::kNone);
  EXPECT_TRUE(r.diagnosis.effects.empty());
  ASSERT_TRUE(r.sessions);
  DiagnoseOptions options;
  options.bootstrap_rounds = SelftestOptions{}.bootstrap_rounds;
  const DiagnosisResult again =
      diagnose_in_detail(r.sessions->calibration, r.sessions->heldout, options);
  EXPECT_EQ(again.diagnosis.status, Status::kNone);
  const std::vector<std::string>& reasons = again.detail.reasons;
  EXPECT_TRUE(std::any_of(reasons.begin(), reasons.end(), [](const std::string& reason) {
    return reason.find("thermal_lag would take") != std::string::npos &&
           reason.find("a fit of the noise's residue") != std::string::npos;
  })) << "reasons: " << ::testing::PrintToString(reasons);
}

// Two short cases on two threads (run_in_parallel), each a whole diagnosis with its own threads:
// each gives what it gives run alone on one thread. The ThreadSanitizer build's test of the
// self-test's threads (scripts/reliability.sh --tsan), small enough to finish there.
TEST(DiagnoseSelftest, CasesOnTwoThreadsGiveWhatEachGivesAlone) {
  SelftestOptions options;
  options.cases = 2;
  options.seed = 1;
  options.duration_s = 600.0;
  options.bootstrap_rounds = 20;
  options.jobs = 2;
  const std::vector<SelftestCaseResult> together = run_selftest(options);
  ASSERT_EQ(together.size(), 2u);
  for (int index = 1; index <= 2; ++index) {
    SelftestOptions one = options;
    one.only_case = index;
    one.jobs = 1;
    const std::vector<SelftestCaseResult> alone = run_selftest(one);
    ASSERT_EQ(alone.size(), 1u);
    const Diagnosis& a = alone.front().diagnosis;
    const Diagnosis& t = together[static_cast<std::size_t>(index - 1)].diagnosis;
    EXPECT_EQ(t.status, a.status) << index;
    EXPECT_EQ(t.heldout_rms_after, a.heldout_rms_after) << index;
    ASSERT_EQ(t.effects.size(), a.effects.size()) << index;
    for (std::size_t e = 0; e < a.effects.size(); ++e) {
      EXPECT_EQ(t.effects[e].name, a.effects[e].name) << index;
      EXPECT_EQ(t.effects[e].params, a.effects[e].params) << index;
      EXPECT_EQ(t.effects[e].inclusion, a.effects[e].inclusion) << index;
    }
  }
}

// A short pair (case 7 of seed 1: mains pickup and a channel skew) takes the diagnosis through
// both passes at once, a library pick given a free shape of its class, and the final fit's
// inclusion shares, each on threads of its own: both classes are named, nothing else, and the
// pick so refined says so. The ThreadSanitizer build's test of those threads.
TEST(DiagnoseSelftest, AShortPairIsNamedWithAPickGivenAFreeShape) {
  const SelftestCaseSpec spec = draw_selftest_case(7, 1);
  ASSERT_EQ(spec.kind, SelftestKind::kPair);
  const SelftestRecordings rec = make_selftest_recordings(spec, 600.0);
  DiagnoseOptions options;
  options.bootstrap_rounds = 20;
  options.seed = 8;  // as the self-test seeds case 7 of seed 1
  const Diagnosis diagnosis = diagnose_in_detail(rec.calibration, rec.heldout, options).diagnosis;
  const SelftestScore score = score_selftest_case(spec, diagnosis, rec.noise_std_v);
  EXPECT_EQ(diagnosis.status, Status::kExplained);
  EXPECT_TRUE(score.all_found) << ::testing::PrintToString(score.claimed);
  EXPECT_EQ(score.spurious, 0);
  EXPECT_TRUE(
      std::any_of(diagnosis.effects.begin(), diagnosis.effects.end(), [](const EffectFinding& f) {
        return f.evidence.find("given a free shape of its class") != std::string::npos;
      }));
  for (const EffectFinding& f : diagnosis.effects) {
    EXPECT_GT(f.inclusion, 0.5) << f.name;
  }
}

TEST(DiagnoseSelftestCommand, SmallBlindSetMeetsTheAims) {
  const auto dir = testing::fresh_test_dir("diagnose_selftest");
  std::ostringstream out, err;
  const int status = cli::run_flange({"diagnose", "--selftest", "--cases", "10", "--seed", "1",
                                      "--bootstrap", "40", "--out", dir.string()},
                                     out, err);
  EXPECT_EQ(status, 0) << out.str() << err.str();
  EXPECT_NE(out.str().find("aims met"), std::string::npos) << out.str();
  std::ifstream in(dir / "selftest.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  ASSERT_EQ(j["cases"].size(), 10u);
  EXPECT_EQ(j["summary"]["null_claims"], 0);
  for (const auto& c : j["cases"]) {
    if (c["kind"] == "null") {
      EXPECT_TRUE(c["claimed"].empty()) << c.dump();
    }
  }
  EXPECT_TRUE(std::filesystem::exists(dir / "selftest.md"));
}

TEST(DiagnoseSelftestCommand, OneCaseWritesItsSessionsInTheRecordingFormat) {
  const auto dir = testing::fresh_test_dir("diagnose_selftest_case");
  std::ostringstream out, err;
  // Case 8 is a null case: a short one runs in a second.
  const int status =
      cli::run_flange({"diagnose", "--selftest", "--case", "8", "--seed", "1", "--duration", "600",
                       "--bootstrap", "20", "--out", dir.string()},
                      out, err);
  EXPECT_EQ(status, 0) << out.str() << err.str();
  const SelftestRecordings expected = make_selftest_recordings(draw_selftest_case(8, 1), 600);
  for (const auto& [name, series] :
       {std::pair{"calibration", &expected.calibration}, std::pair{"heldout", &expected.heldout}}) {
    const RecordingSeries read =
        read_recording_series((dir / (std::string("case_8_") + name + ".csv")).string());
    ASSERT_EQ(read.size(), series->size()) << name;
    EXPECT_NEAR(read.voltage_v.back(), series->voltage_v.back(), 1e-6) << name;
  }
}

TEST(DiagnoseSelftestCommand, BadArgumentsGiveStatusTwo) {
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"diagnose", "--selftest", "--cases", "0"},
        std::vector<std::string>{"diagnose", "--selftest", "--duration", "10"},
        std::vector<std::string>{"diagnose", "--selftest", "--real", "real.csv"}}) {
    std::ostringstream out, err;
    EXPECT_EQ(cli::run_flange(args, out, err), 2) << args.back();
    EXPECT_NE(err.str().find(args[2]), std::string::npos) << err.str();
  }
}

}  // namespace
}  // namespace flange::diagnose
