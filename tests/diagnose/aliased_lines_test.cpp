// SPDX-License-Identifier: MIT
// Mains pickup and mount motion folded onto one line: at 6 Hz, 50 Hz and motion at 14 Hz both land
// on 2 Hz. Where the clearance and temperature move, the line's amplitude follows the sensor's
// sensitivity dV/dd for motion and not for pickup, and the diagnosis names the right one; where
// they are constant the data cannot tell, and it names both at half confidence or less with a
// sample rate that would separate them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <regex>
#include <string>
#include <vector>

#include "criteria.h"
#include "diagnosis_detail.h"
#include "separating_rate.h"
#include "twin_recording.h"

namespace flange::diagnose {
namespace {

constexpr double kFsHz = 6.0;
constexpr double kDurationS = 1800.0;
constexpr double kMotionHz = 14.0;  // folds to 2 Hz at 6 Hz, as 50 Hz does
constexpr double kMainsHz = 50.0;

// The oven swept up and down over 20-90 degC once per session.
double swept_c(double t) {
  const double u = t / kDurationS;
  return 20.0 + 70.0 * (u < 0.5 ? 2.0 * u : 2.0 - 2.0 * u);
}

sim::EffectSettings motion_on_the_alias() {
  return sim::make_effect_settings(
      "vibration",
      {{"rms_mm", 0.05}, {"f_low_hz", kMotionHz - 0.05}, {"f_high_hz", kMotionHz + 0.05}},
      "test");
}

sim::EffectSettings mains() {
  return sim::make_effect_settings("mains_pickup", {{"amplitude_v", 0.06}, {"harmonics", 1}},
                                   "test");
}

// Two sessions of the twin with `effect` and 20 mV of noise: over the staircase and the sweep
// (`moving`), or at 5 mm and 40 degC throughout, where dV/dd does not change.
DiagnosisResult diagnose_pair(const sim::EffectSettings& effect, bool moving) {
  sim::TwinConfig config;
  config.noise.voltage_std_v = 0.02;
  config.effects = {effect};
  const auto session = [&](std::uint64_t seed) {
    if (moving) return record_twin(config, seed, kFsHz, kDurationS, staircase_mm, swept_c);
    return record_twin(config, seed, kFsHz, kDurationS, [](double) { return 5.0; },
                       [](double) { return 40.0; });
  };
  return diagnose_in_detail(session(11), session(12), {});
}

std::string named(const DiagnosisResult& r) {
  std::string out = "verdict " + std::to_string(static_cast<int>(r.diagnosis.status)) + "\n";
  for (const EffectFinding& f : r.diagnosis.effects) {
    out += f.name + " confidence " + std::to_string(f.confidence) + ": " + f.evidence + "\n";
  }
  for (const std::string& s : r.diagnosis.next_measurement) out += "next: " + s + "\n";
  return out;
}

bool names(const Diagnosis& d, const std::string& name) {
  return std::any_of(d.effects.begin(), d.effects.end(), [&](const EffectFinding& f) {
    return f.name == name || std::find(f.indistinguishable_from.begin(),
                                       f.indistinguishable_from.end(),
                                       name) != f.indistinguishable_from.end();
  });
}

TEST(AliasedLines, TheSeparatingRateFoldsTheMainsAwayFromEveryMotionOnTheLine) {
  EXPECT_NEAR(folded_hz(kMainsHz, kFsHz), 2.0, 1e-12);
  EXPECT_NEAR(folded_hz(kMotionHz, kFsHz), 2.0, 1e-12);
  const std::optional<double> rate = separating_rate_hz(2.0, kFsHz, {kMainsHz, 2 * kMainsHz});
  ASSERT_TRUE(rate.has_value());
  const double mains_at = folded_hz(kMainsHz, *rate);
  EXPECT_GE(mains_at, kSeparatedLinesHz);
  EXPECT_LE(mains_at, *rate / 2 - kSeparatedLinesHz);
  // Every motion that folds onto 2 Hz at 6 Hz (4, 8, 10, 14, ... Hz), but the mains' own
  // frequencies, folds elsewhere at the new rate.
  for (int k = 0; k <= 17; ++k) {
    for (const double f : {6.0 * k - 2.0, 6.0 * k + 2.0}) {
      if (f <= 0.0 || f > kHighestMotionHz || std::abs(f - 50.0) < 0.3 || std::abs(f - 100) < 0.3)
        continue;
      EXPECT_NEAR(folded_hz(f, kFsHz), 2.0, 1e-9) << f;
      EXPECT_GE(std::abs(folded_hz(f, *rate) - mains_at), kSeparatedLinesHz) << f << " " << *rate;
      EXPECT_GE(std::abs(folded_hz(f, *rate) - folded_hz(100.0, *rate)), kSeparatedLinesHz) << f;
    }
  }
}

TEST(AliasedLines, MotionOnTheMainsAliasWithTheSensitivityChangingIsMotion) {
  const DiagnosisResult r = diagnose_pair(motion_on_the_alias(), true);
  ASSERT_FALSE(r.diagnosis.effects.empty()) << named(r);
  EXPECT_EQ(r.diagnosis.effects.front().name, "vibration") << named(r);
  for (const EffectFinding& f : r.diagnosis.effects) EXPECT_NE(f.name, "mains_pickup") << named(r);
}

TEST(AliasedLines, MainsAloneWithTheSensitivityChangingIsMains) {
  const DiagnosisResult r = diagnose_pair(mains(), true);
  ASSERT_FALSE(r.diagnosis.effects.empty()) << named(r);
  const EffectFinding& top = r.diagnosis.effects.front();
  EXPECT_EQ(top.name, "mains_pickup") << named(r);
  EXPECT_TRUE(top.indistinguishable_from.empty()) << named(r);
  EXPECT_GT(top.confidence, criteria::kMostConfidenceOfIndistinguishable) << named(r);
  EXPECT_FALSE(names(r.diagnosis, "vibration")) << named(r);
}

// At one clearance and temperature the line is the same whichever made it: both are named, at
// confidence 0.5 or less, and the next measurement names a rate at which 50 Hz and 14 Hz (the
// motion that made it) fold apart.
TEST(AliasedLines, ALineTheDataCannotSeparateNamesBothAtHalfConfidenceOrLess) {
  for (const sim::EffectSettings& effect : {motion_on_the_alias(), mains()}) {
    const DiagnosisResult r = diagnose_pair(effect, false);
    ASSERT_FALSE(r.diagnosis.effects.empty()) << effect.name << "\n" << named(r);
    EXPECT_TRUE(names(r.diagnosis, "mains_pickup")) << named(r);
    EXPECT_TRUE(names(r.diagnosis, "vibration")) << named(r);
    for (const EffectFinding& f : r.diagnosis.effects) {
      if (f.name == "mains_pickup" || f.name == "vibration") {
        EXPECT_LE(f.confidence, criteria::kMostConfidenceOfIndistinguishable) << named(r);
      }
    }
    const std::regex sampled_at("sampled at ([0-9.]+) Hz");
    std::smatch m;
    const auto said = std::find_if(
        r.diagnosis.next_measurement.begin(), r.diagnosis.next_measurement.end(),
        [&](const std::string& s) { return std::regex_search(s, m, sampled_at); });
    ASSERT_NE(said, r.diagnosis.next_measurement.end()) << named(r);
    const double rate = std::stod(m[1].str());
    EXPECT_GE(std::abs(folded_hz(kMotionHz, rate) - folded_hz(kMainsHz, rate)),
              kSeparatedLinesHz)
        << rate;
    EXPECT_NE(said->find("clearance"), std::string::npos) << *said;
  }
}

}  // namespace
}  // namespace flange::diagnose
