// SPDX-License-Identifier: MIT
// `flange diagnose --selftest --reality third`: the scoring of pairs with two and three true
// classes (right class first, every class named, the split by class alone and with others, the
// table by number of classes, the aims), and `--case K --out DIR` writing the pair's
// sessions and truth.
#include "third_selftest.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "flange_in_process.h"
#include "recording_series.h"
#include "test_files.h"

namespace flange::diagnose {
namespace {

using third_reality::ThirdPairKind;
using third_reality::ThirdPairSpec;

EffectFinding finding(const std::string& name, std::map<std::string, double> params = {}) {
  EffectFinding f;
  f.name = name;
  f.params = std::move(params);
  return f;
}

ThirdPairSpec spec_with(ThirdPairKind kind, const std::vector<std::string>& classes) {
  ThirdPairSpec spec;
  spec.kind = kind;
  for (const std::string& c : classes) spec.truth.push_back({{c, "any", {}, ""}, 0.05});
  spec.fit.noise_v = spec.heldout.noise_v = 0.03;
  return spec;
}

Diagnosis explained_by(std::vector<EffectFinding> effects, double before, double after) {
  Diagnosis d;
  d.status = Status::kExplained;
  d.effects = std::move(effects);
  d.heldout_rms_before = before;
  d.heldout_rms_after = after;
  return d;
}

ThirdPairResult result_of(const ThirdPairSpec& spec, const Diagnosis& d) {
  ThirdPairResult r;
  r.spec = spec;
  r.diagnosis = d;
  r.score = score_third_pair(spec, d, {});
  return r;
}

TEST(ThirdSelftest, PairsOfTwoAndThreeClassesAreScoredByClassAndByCount) {
  const ThirdPairSpec three = spec_with(
      ThirdPairKind::kMulti, {"sensor_thermal_lag", "temperature_offset", "mains_pickup"});
  // Two of the three named, the right one first, the gap above the noise shrunk by 3/4.
  const Diagnosis two_of_three = explained_by(
      {finding("temp_offset_drift"), finding("mains_pickup")}, 0.05, std::hypot(0.01, 0.03));
  const BlindScore s = score_third_pair(three, two_of_three, {});
  EXPECT_TRUE(s.top_correct);
  EXPECT_FALSE(s.all_found);
  EXPECT_EQ(s.spurious, 0);
  EXPECT_NEAR(s.excess_shrink_pct, 75.0, 1e-9);

  const ThirdPairSpec two = spec_with(ThirdPairKind::kMulti, {"ageing", "channel_skew"});
  const Diagnosis both = explained_by(
      {finding("ageing_drift"), finding("channel_skew", {{"skew_s", -2.0}})}, 0.05, 0.03);
  const ThirdPairSpec single = spec_with(ThirdPairKind::kSingle, {"ageing"});
  const Diagnosis wrong = explained_by({finding("temp_gain_drift")}, 0.05, 0.03);
  Diagnosis none;
  none.status = Status::kNone;
  const Diagnosis claim_on_null = explained_by({finding("vibration")}, 0.05, 0.04);
  const std::vector<ThirdPairResult> results = {
      result_of(three, two_of_three), result_of(two, both), result_of(single, wrong),
      result_of(spec_with(ThirdPairKind::kNull, {}), none),
      result_of(spec_with(ThirdPairKind::kNull, {}), claim_on_null)};
  const BlindSummary summary = summarise_third_selftest(results);
  ASSERT_EQ(summary.by_effects.size(), 3u);
  EXPECT_EQ(summary.by_effects[0].effects, 1);
  EXPECT_EQ(summary.by_effects[0].top_correct, 0);
  EXPECT_EQ(summary.by_effects[1].effects, 2);
  EXPECT_EQ(summary.by_effects[1].all_found, 1);
  EXPECT_EQ(summary.by_effects[2].effects, 3);
  EXPECT_EQ(summary.by_effects[2].top_correct, 1);
  EXPECT_EQ(summary.by_effects[2].all_found, 0);
  for (const BlindClassRow& row : summary.classes) {
    if (row.name == "ageing") {
      EXPECT_EQ(row.alone, 1);
      EXPECT_EQ(row.alone_top, 0);
      EXPECT_EQ(row.shared, 1);
      EXPECT_EQ(row.shared_named, 1);
    }
    if (row.name == "sensor_thermal_lag") {
      EXPECT_EQ(row.shared_named, 0);
    }
  }
  const ThirdAims aims = third_aims(summary);
  EXPECT_EQ(aims.singles, 1);
  EXPECT_FALSE(aims.singles_met);
  EXPECT_EQ(aims.multiples, 2);
  EXPECT_EQ(aims.multiples_top, 2);
  EXPECT_TRUE(aims.multiples_top_met);
  EXPECT_EQ(aims.multiples_all, 1);
  EXPECT_FALSE(aims.multiples_all_met);
  EXPECT_EQ(aims.controls, 2);
  EXPECT_EQ(aims.controls_quiet, 1);
  EXPECT_FALSE(aims.controls_met);
  EXPECT_FALSE(aims.met());
}

TEST(ThirdSelftestCommand, OnePairWritesItsSessionsAndItsTruth) {
  const auto dir = testing::fresh_test_dir("third_selftest_pair");
  const testing::FlangeOutcome o = testing::run_flange_captured(
      {"diagnose", "--selftest", "--reality", "third", "--case", "8", "--seed", "3", "--duration",
       "600", "--bootstrap", "20", "--out", dir.string()});
  EXPECT_TRUE(o.status == 0 || o.status == 1) << o.err;  // 1: an aim missed, not an error
  EXPECT_NE(o.out.find("--reality third: 1 pairs, seed 3"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("By number of true classes"), std::string::npos) << o.out;
  for (const char* file : {"pair_8_fit.csv", "pair_8_heldout.csv", "pair_8_truth.json",
                           "selftest.json", "selftest.md"}) {
    EXPECT_TRUE(std::filesystem::exists(dir / file)) << file;
  }
  std::ifstream in(dir / "selftest.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j["reality"], "third");
  ASSERT_EQ(j["pairs"].size(), 1u);
  EXPECT_EQ(j["pairs"][0]["kind"], "null");
  std::ifstream truth_in(dir / "pair_8_truth.json");
  const nlohmann::json truth = nlohmann::json::parse(truth_in);
  const double fs = truth["fit_session"]["fs_hz"].get<double>();
  const double duration = truth["fit_session"]["duration_s"].get<double>();
  const RecordingSeries fit = read_recording_series((dir / "pair_8_fit.csv").string());
  EXPECT_LT(static_cast<double>(fit.size()), duration * fs + 1.0);  // the logger lost rows
  EXPECT_GT(static_cast<double>(fit.size()), 0.95 * duration * fs);
}

}  // namespace
}  // namespace flange::diagnose
