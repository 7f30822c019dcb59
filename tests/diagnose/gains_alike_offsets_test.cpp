// SPDX-License-Identifier: MIT
// A gain about a pivot far off the recorded voltages changes with the voltage by less than the
// noise can tell, so a curve of the temperature alone follows it and the pick names an offset
// too; a gain about a pivot among the recorded voltages, or a curve the temperature alone does
// not follow on the held-out part, is not a curve of the temperature.
#include "gains_alike_offsets.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>
#include <random>
#include <vector>

#include "curve_alike.h"
#include "flange_in_process.h"
#include "test_files.h"
#include "third_pair.h"

namespace flange::diagnose {
namespace {

constexpr double kNoise = 0.01;
constexpr int kKnots = 7;

struct TwoParts {
  std::vector<double> cal_t, cal_curve, ho_t, ho_curve, ho_left;
};

// Voltages of 1-8 V and temperatures of 20-80 degC drawn independently; the pick's curve is
// (V - pivot) h(T), h(T) = gain sin(pi (T - 20) / 60); what it leaves of the held-out gap is white
// noise of kNoise (it explains the gap). `ho_shift_c` moves the held-out part's recorded
// temperature away from the one the curve follows.
TwoParts gain_about(double pivot_v, double gain, double ho_shift_c = 0.0) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> voltage(1.0, 8.0), temperature(20.0, 80.0);
  std::normal_distribution<double> noise(0.0, kNoise);
  TwoParts p;
  const auto h = [gain](double t) { return gain * std::sin(std::numbers::pi * (t - 20.0) / 60.0); };
  for (int i = 0; i < 4000; ++i) {
    for (const bool cal : {true, false}) {
      const double v = voltage(rng), t = temperature(rng);
      (cal ? p.cal_t : p.ho_t).push_back(cal ? t : std::clamp(t + ho_shift_c, 20.0, 80.0));
      (cal ? p.cal_curve : p.ho_curve).push_back((v - pivot_v) * h(t));
      if (!cal) p.ho_left.push_back(noise(rng));
    }
  }
  return p;
}

bool a_curve_of_temperature(const TwoParts& p) {
  return curve_of_one_variable_alike(p.cal_t, p.cal_curve, p.ho_t, p.ho_curve, p.ho_left, kNoise,
                                     kKnots)
      .has_value();
}

TEST(GainsAlikeOffsets, AGainAboutAFarPivotIsACurveOfTheTemperature) {
  // About -40 V: 0.02 V at the curve's peak, of which the voltage's 1-8 V move 0.001 V RMS.
  EXPECT_TRUE(a_curve_of_temperature(gain_about(-40.0, 0.0005)));
}

TEST(GainsAlikeOffsets, AGainAboutAPivotAmongTheVoltagesIsNot) {
  // About 4.5 V, mid-range: the same 0.02 V, all of it changing with the voltage.
  EXPECT_FALSE(a_curve_of_temperature(gain_about(4.5, 0.006)));
  // About -40 V but ten times larger: the voltage's share stands out of the noise.
  EXPECT_FALSE(a_curve_of_temperature(gain_about(-40.0, 0.005)));
}

TEST(GainsAlikeOffsets, ACurveTheHeldOutPartDoesNotConfirmIsNot) {
  // The held-out part's temperatures read 15 degC off what the curve follows: the curve of the
  // recorded temperature leaves far more there than the pick.
  EXPECT_FALSE(a_curve_of_temperature(gain_about(-40.0, 0.0005, 15.0)));
}

TEST(GainsAlikeOffsets, NoCurveForEmptyOrMismatchedInputs) {
  EXPECT_FALSE(curve_of_one_variable_alike({}, {}, {}, {}, {}, kNoise, kKnots));
  EXPECT_FALSE(curve_of_one_variable_alike({20.0, 30.0}, {0.1}, {}, {}, {}, kNoise, kKnots));
  EXPECT_FALSE(curve_of_one_variable_alike({25.0, 25.0}, {0.1, 0.2}, {}, {}, {}, kNoise, kKnots));
}

TEST(GainsAlikeOffsets, TheNextMeasurementNamesThePivot) {
  EffectFinding pick;
  pick.name = "temp_gain_drift";
  pick.params["pivot_v"] = -39.1;
  const std::string next = tell_gain_from_offset(pick, "temp_offset_drift");
  EXPECT_NE(next.find("to tell temp_gain_drift from temp_offset_drift"), std::string::npos) << next;
  EXPECT_NE(next.find("about a pivot at -39.1 V"), std::string::npos) << next;
}

// The third reality's seed 485 (a seed that may set rules) pair 12: a range compression, after
// which a small gain curve of the temperature about 4.3 V is picked too; its change with the
// voltage is below the noise, so the diagnosis names it alike an offset, with what would tell.
TEST(GainsAlikeOffsets, ASmallGainOnTheThirdRealityIsNamedAlikeAnOffset) {
  const auto dir = testing::fresh_test_dir("gain_alike_offset_pair");
  testing::write_third_pair(485, 12, dir);
  const nlohmann::json diagnosis = testing::diagnose_third_pair(dir, 12);
  ASSERT_FALSE(diagnosis.is_null());
  const auto& effects = diagnosis["effects"];
  const auto gain = std::find_if(effects.begin(), effects.end(),
                                 [](const nlohmann::json& e) { return e["name"] == "temp_gain_drift"; });
  ASSERT_NE(gain, effects.end()) << diagnosis.dump();
  EXPECT_EQ((*gain)["indistinguishable_from"], nlohmann::json::array({"temp_offset_drift"}));
  EXPECT_LE((*gain)["confidence"].get<double>(), 0.5);
  const std::string next = diagnosis["next_measurement"].dump();
  EXPECT_NE(next.find("to tell temp_gain_drift from temp_offset_drift"), std::string::npos) << next;
}

}  // namespace
}  // namespace flange::diagnose
