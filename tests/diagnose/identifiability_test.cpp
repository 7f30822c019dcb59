// SPDX-License-Identifier: MIT
// What the data can tell: a temperature law is undetermined on a session at room temperature or
// within a few degrees of it, with its gain there reported, and determined on a full sweep;
// a recording of one operating point names every class that shifts it and says it is degenerate,
// no parameter is reported at the edge of its search, the held-out data must be another session,
// and nothing but the results reaches standard output.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <random>
#include <stdexcept>

#include "compensated_sensitivity.h"
#include "confidence.h"
#include "criteria.h"
#include "diagnosis.h"
#include "diagnosis_detail.h"
#include "effect_classes.h"
#include "flange_in_process.h"
#include "polynomial_sensor_model.h"
#include "test_files.h"
#include "twin_recording.h"
#include "verdict_reasons.h"

namespace flange::diagnose {
namespace {

using testing::FlangeOutcome;
using testing::fresh_test_dir;
using testing::run_flange_captured;

constexpr double kFsHz = 6.0;

double rounded(double v, double quantum) { return std::round(v / quantum) * quantum; }

// A bench session at room temperature: the recorded temperature reads 21.9 or 22.0 degC all
// through, the sensor reads `gain` times the nominal voltage, with 2 mV of noise, recorded to
// 0.1 mV.
RecordingSeries room_temperature_session(double gain, std::uint64_t seed, double duration_s) {
  const sim::PolynomialSensorModel model = sim::PolynomialSensorModel::thesis_eq_3_14();
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0.0, 0.002);
  std::bernoulli_distribution warmer(0.5);
  RecordingSeries s;
  for (int i = 0; i < static_cast<int>(duration_s * kFsHz); ++i) {
    const double t = i / kFsHz;
    s.t_s.push_back(t);
    s.clearance_mm.push_back(staircase_mm(t));
    s.temp_c.push_back(warmer(rng) ? 22.0 : 21.9);
    const double v = model.voltage_for(s.clearance_mm.back(), s.temp_c.back()).volts;
    s.voltage_v.push_back(rounded(gain * v + noise(rng), 1e-4));
  }
  return s;
}

// The micrometer never moved, the temperature held: 5 mm, 22 degC, the voltage `offset_v` off the
// nominal and exactly repeated.
RecordingSeries one_operating_point(double offset_v, double duration_s) {
  const sim::PolynomialSensorModel model = sim::PolynomialSensorModel::thesis_eq_3_14();
  const double v = rounded(model.voltage_for(5.0, 22.0).volts + offset_v, 1e-4);
  RecordingSeries s;
  for (int i = 0; i < static_cast<int>(duration_s * kFsHz); ++i) {
    s.t_s.push_back(i / kFsHz);
    s.clearance_mm.push_back(5.0);
    s.temp_c.push_back(22.0);
    s.voltage_v.push_back(v);
  }
  return s;
}

DiagnosisResult diagnose_pair(const RecordingSeries& cal, const RecordingSeries& ho) {
  DiagnoseOptions options;
  options.bootstrap_rounds = 20;
  return diagnose_in_detail(cal, ho, options);
}

bool has(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

// No parameter of a library class is reported at an edge of its search.
void expect_no_value_at_a_search_edge(const EffectFinding& f) {
  const EffectClass& c = effect_class(f.name);
  for (const SearchRange& range : c.search) {
    const auto at = f.params.find(range.key);
    if (at == f.params.end() || has(f.undetermined, range.key) || f.bounds.count(range.key)) {
      continue;
    }
    const double edge = 1e-3 * (range.hi - range.lo);
    EXPECT_GT(at->second, range.lo + edge) << f.name << " " << range.key;
    EXPECT_LT(at->second, range.hi - edge) << f.name << " " << range.key;
  }
}

TEST(Identifiability, ATemperatureLawIsUndeterminedAtRoomTemperature) {
  const DiagnosisResult r = diagnose_pair(room_temperature_session(1.02, 1, 1800.0),
                                          room_temperature_session(1.02, 2, 1800.0));
  const Diagnosis& d = r.diagnosis;
  ASSERT_EQ(d.status, Status::kExplained);
  ASSERT_FALSE(d.effects.empty());
  EXPECT_TRUE(std::any_of(d.degenerate.begin(), d.degenerate.end(), [](const std::string& s) {
    return s.find("temperature takes only 2 distinct values") != std::string::npos;
  }));
  for (const EffectFinding& f : d.effects) {
    expect_no_value_at_a_search_edge(f);
    // Whatever class carries the gain, a law of the temperature is not claimed.
    for (const char* law : {"gain_per_c", "reference_c", "offset_v_per_c"}) {
      if (f.params.count(law)) {
        EXPECT_TRUE(has(f.undetermined, law)) << f.name << " " << law;
      }
    }
  }
  EXPECT_FALSE(d.next_measurement.empty());
}

// The twin's gain drifting with the temperature, 2.5e-3 per degC from 15 degC (1.75 % high at
// 22 degC, 16 % at 80 degC), 20 mV of noise, over the micrometer's staircase for 30 min, with
// the oven at 22 degC wandering by +-`wander_c` over 700 s, or (`wander_c` < 0) swept up and down
// over 20-98 degC, as the bench's blower does.
constexpr double kGainPerC = 2.5e-3, kReferenceC = 15.0;
RecordingSeries gain_drift_session(double wander_c, std::uint64_t seed, double phase_s) {
  sim::TwinConfig config;
  config.noise.voltage_std_v = 0.02;
  config.effects = {sim::make_effect_settings(
      "temp_gain_drift", {{"gain_per_c", kGainPerC}, {"reference_c", kReferenceC}}, "test")};
  const auto clearance = [phase_s](double t) { return staircase_mm(t + phase_s); };
  const auto temperature = [wander_c, phase_s](double t) {
    if (wander_c < 0.0) {
      const double u = std::fmod(t + phase_s, 1800.0) / 1800.0;
      return 20.0 + 78.0 * (u < 0.5 ? 2.0 * u : 2.0 - 2.0 * u);
    }
    return 22.0 + wander_c * std::sin(2.0 * std::numbers::pi * (t + phase_s) / 700.0);
  };
  return record_twin(config, seed, kFsHz, 1800.0, clearance, temperature);
}

const EffectFinding& the_gain_drift(const Diagnosis& d) {
  const auto it = std::find_if(d.effects.begin(), d.effects.end(),
                               [](const EffectFinding& f) { return f.name == "temp_gain_drift"; });
  if (it == d.effects.end()) throw std::runtime_error("no temp_gain_drift found");
  return *it;
}

TEST(Identifiability, ATemperatureLawHeldWithinAFewDegreesIsUndetermined) {
  // Exactly constant, within +-0.2 degC and within +-2 degC: a slope fitted over 4 degC at most is
  // extrapolated over 20-98 degC, where the slopes the data allow part by more than the noise.
  for (const double wander_c : {0.0, 0.2, 2.0}) {
    const DiagnosisResult r =
        diagnose_pair(gain_drift_session(wander_c, 1, 0.0), gain_drift_session(wander_c, 2, 333.0));
    const Diagnosis& d = r.diagnosis;
    ASSERT_EQ(d.status, Status::kExplained) << wander_c;
    const EffectFinding& f = the_gain_drift(d);
    EXPECT_TRUE(has(f.undetermined, "gain_per_c")) << wander_c;
    EXPECT_TRUE(has(f.undetermined, "reference_c")) << wander_c;
    // The gain at the recorded temperature is what the data fix: within 6 % of the truth.
    ASSERT_TRUE(f.level.has_value()) << wander_c;
    EXPECT_EQ(f.level->key, "gain_change");
    EXPECT_NEAR(f.level->value, kGainPerC * (f.level->temp_c - kReferenceC), 1e-3) << wander_c;
    EXPECT_LT(f.level->resolution, 1e-3) << wander_c;
    const auto sweep = std::find_if(
        d.next_measurement.begin(), d.next_measurement.end(), [](const std::string& s) {
          return s.find("to determine gain_per_c and reference_c of temp_gain_drift: a session "
                        "that sweeps the temperature") != std::string::npos;
        });
    ASSERT_NE(sweep, d.next_measurement.end()) << wander_c;
    // A sweep a bench can run: from room temperature up, not about 22 degC into the cold.
    double lowest_c = 0.0, highest_c = 0.0;
    ASSERT_EQ(std::sscanf(sweep->substr(sweep->find('(')).c_str(), "(%lf to %lf degC)", &lowest_c,
                          &highest_c),
              2)
        << *sweep;
    EXPECT_GE(lowest_c, criteria::kOperatingRangeLowestC) << *sweep;
  }
}

TEST(Identifiability, ATemperatureLawSweptOverTheRangeIsDetermined) {
  const DiagnosisResult r =
      diagnose_pair(gain_drift_session(-1.0, 1, 0.0), gain_drift_session(-1.0, 2, 333.0));
  const Diagnosis& d = r.diagnosis;
  ASSERT_EQ(d.status, Status::kExplained);
  const EffectFinding& f = the_gain_drift(d);
  EXPECT_TRUE(f.undetermined.empty());
  EXPECT_TRUE(f.bounds.empty());
  EXPECT_NEAR(f.params.at("gain_per_c"), kGainPerC, 0.05 * kGainPerC);
  EXPECT_NEAR(f.params.at("reference_c"), kReferenceC, 1.0);
  EXPECT_TRUE(std::none_of(d.next_measurement.begin(), d.next_measurement.end(),
                           [](const std::string& s) { return s.find("to determine") == 0; }));
}

TEST(Identifiability, AConstantRecordingNamesEveryClassThatShiftsItsOnePoint) {
  // 0.3 V below the twin: within reach of every class that shifts a voltage (1.56 V is beyond
  // the temperature offset's search at 22 degC, and the data then rule it out).
  const RecordingSeries whole = one_operating_point(-0.3, 1200.0);
  const HoldoutSplit split = split_holdout(whole, 0.3);
  const DiagnosisResult r = diagnose_pair(split.calibration, split.heldout);
  const Diagnosis& d = r.diagnosis;
  ASSERT_FALSE(d.effects.empty()) << d.status;
  const EffectFinding& named = d.effects.front();
  std::vector<std::string> alike = named.indistinguishable_from;
  alike.push_back(named.name);
  for (const char* shifts : {"temp_offset_drift", "ageing_drift", "range_compression"}) {
    EXPECT_TRUE(has(alike, shifts)) << shifts;
  }
  for (const auto& [key, value] : named.params) {
    EXPECT_TRUE(has(named.undetermined, key) || named.bounds.count(key)) << key << "=" << value;
  }
  for (const char* what : {"clearance is constant", "temperature is constant",
                           "voltage is constant", "noise estimate is zero"}) {
    EXPECT_TRUE(std::any_of(d.degenerate.begin(), d.degenerate.end(), [&](const std::string& s) {
      return s.find(what) != std::string::npos;
    })) << what;
  }
  EXPECT_FALSE(r.detail.band_hz.has_value());
  EXPECT_TRUE(r.detail.segments.empty());
  EXPECT_FALSE(d.next_measurement.empty());
}

TEST(Identifiability, ConfidenceIsTheBaseRateOfItsPlaceSharedAmongAlikeClasses) {
  EffectFinding f;
  f.inclusion = 1.0;
  EXPECT_DOUBLE_EQ(confidence_of(f, ClaimPlace::alone, Status::kExplained),
                   criteria::kAloneClaimAccuracy);
  EXPECT_DOUBLE_EQ(confidence_of(f, ClaimPlace::first_of_several, Status::kExplained),
                   criteria::kFirstOfSeveralClaimAccuracy);
  EXPECT_DOUBLE_EQ(confidence_of(f, ClaimPlace::later, Status::kExplained),
                   criteria::kLaterClaimAccuracy);
  f.inclusion = 0.5;
  f.indistinguishable_from = {"ageing_drift"};
  EXPECT_DOUBLE_EQ(confidence_of(f, ClaimPlace::alone, Status::kExplained),
                   criteria::kAloneClaimAccuracy * 0.5 / 2.0);
}

// A curve of the clearance named alone takes a base rate of its own: its free curve takes up
// whatever static shape the data hold (a compression whose knee does not move with temperature, a
// hysteresis reached from one side), so it is right less often than a class of another kind.
TEST(Identifiability, ACurveOfTheClearanceNamedAloneHasABaseRateOfItsOwn) {
  EffectFinding f;
  f.name = "nonlinearity";
  f.inclusion = 1.0;
  ASSERT_TRUE(effect_class(f.name).function_of_clearance_alone);
  EXPECT_DOUBLE_EQ(confidence_of(f, ClaimPlace::alone, Status::kExplained),
                   criteria::kAloneCurveOfClearanceClaimAccuracy);
  EXPECT_LT(criteria::kAloneCurveOfClearanceClaimAccuracy, criteria::kAloneClaimAccuracy);
  EXPECT_DOUBLE_EQ(confidence_of(f, ClaimPlace::first_of_several, Status::kExplained),
                   criteria::kFirstOfSeveralClaimAccuracy);
  f.name = "temp_gain_drift";
  ASSERT_FALSE(effect_class(f.name).function_of_clearance_alone);
  EXPECT_DOUBLE_EQ(confidence_of(f, ClaimPlace::alone, Status::kExplained),
                   criteria::kAloneClaimAccuracy);
}

// A class named alone is trusted more than the first of several, which shapes outside the library
// split between, and a later one least; a partly explained verdict's classes have rates of their own.
TEST(Identifiability, AVerdictsPlacesGiveItsClassesTheirBaseRates) {
  EffectFinding a;
  a.name = "temp_gain_drift";
  a.inclusion = 1.0;
  EffectFinding b = a;
  b.name = "nonlinearity";
  const std::vector<EffectFinding> one = with_confidences({a}, Status::kExplained);
  EXPECT_DOUBLE_EQ(one[0].confidence, criteria::kAloneClaimAccuracy);
  const std::vector<EffectFinding> two = with_confidences({a, b}, Status::kExplained);
  EXPECT_DOUBLE_EQ(two[0].confidence, criteria::kFirstOfSeveralClaimAccuracy);
  EXPECT_DOUBLE_EQ(two[1].confidence, criteria::kLaterClaimAccuracy);
  EXPECT_GT(criteria::kAloneClaimAccuracy, criteria::kFirstOfSeveralClaimAccuracy);
  // A partly explained verdict's classes take its own base rates, the first (or only) one and the
  // later ones: what is left of the gap is something none of them models, which may have lent
  // them part of its shape; a class the data cannot tell from another still shares it.
  EXPECT_DOUBLE_EQ(with_confidences({b}, Status::kPartlyExplained)[0].confidence,
                   criteria::kPartlyExplainedFirstClaimAccuracy);
  const std::vector<EffectFinding> partly = with_confidences({a, b}, Status::kPartlyExplained);
  EXPECT_DOUBLE_EQ(partly[0].confidence, criteria::kPartlyExplainedFirstClaimAccuracy);
  EXPECT_DOUBLE_EQ(partly[1].confidence, criteria::kPartlyExplainedLaterClaimAccuracy);
  b.indistinguishable_from = {"range_compression"};
  EXPECT_LE(with_confidences({b}, Status::kPartlyExplained)[0].confidence,
            criteria::kMostConfidenceOfIndistinguishable);
}

TEST(CompensatedSensitivity, ACopyOfAnotherColumnHasNone) {
  Eigen::MatrixXd columns(100, 3);
  for (int i = 0; i < 100; ++i) {
    columns(i, 0) = std::sin(0.1 * i);
    columns(i, 1) = 2.0 * columns(i, 0);
    columns(i, 2) = (i % 2 == 0) ? 1.0 : -1.0;
  }
  const Eigen::VectorXd s = compensated_sensitivity(columns.transpose() * columns, 100);
  EXPECT_NEAR(s(0), 0.0, 1e-6);
  EXPECT_NEAR(s(1), 0.0, 1e-6);
  EXPECT_GT(s(2), 0.9);  // nearly orthogonal to the sine: about its own RMS, 1
}

TEST(CompensatedSensitivity, AnOrthogonalColumnKeepsItsOwnRms) {
  Eigen::MatrixXd columns = Eigen::MatrixXd::Zero(4, 2);
  columns << 1, 1, 1, -1, -1, 1, -1, -1;
  const Eigen::VectorXd s = compensated_sensitivity(columns.transpose() * columns, 4);
  EXPECT_NEAR(s(0), 1.0, 1e-12);
  EXPECT_NEAR(s(1), 1.0, 1e-12);
}

TEST(CompensatedSensitivity, ACombinationTheDataSeeKeepsItsSensitivityWhereItsPartsHaveNone) {
  // A level g (T - T_ref) at one temperature: the columns of g and T_ref are copies of each other
  // (scaled), so neither value has any sensitivity, but the level they make has.
  Eigen::MatrixXd columns(100, 2);
  for (int i = 0; i < 100; ++i) {
    columns(i, 0) = 7.0 * (1.0 + 0.01 * i);     // d/dg = (T - T_ref) w
    columns(i, 1) = -0.0025 * (1.0 + 0.01 * i);  // d/dT_ref = -g w
  }
  const Eigen::MatrixXd gram = columns.transpose() * columns;
  EXPECT_NEAR(compensated_sensitivity(gram, 100)(0), 0.0, 1e-6);
  const double w_rms = columns.col(0).norm() / std::sqrt(100.0) / 7.0;
  // The level's gradient (T - T_ref, -g): it moves the voltage by w per unit.
  EXPECT_NEAR(combination_sensitivity(gram, 100, Eigen::Vector2d(7.0, -0.0025)), w_rms, 1e-9);
  // Moving g alone is a direction the data do not see.
  EXPECT_EQ(combination_sensitivity(gram, 100, Eigen::Vector2d(1.0, 0.0)), 0.0);
  // A single column's own gradient is its compensated sensitivity.
  const Eigen::MatrixXd one = columns.col(0);
  EXPECT_NEAR(combination_sensitivity(one.transpose() * one, 100, Eigen::VectorXd::Ones(1)),
              compensated_sensitivity(one.transpose() * one, 100)(0), 1e-12);
}

void write_csv(const std::filesystem::path& path, const RecordingSeries& s) {
  std::ofstream csv(path, std::ios::binary);
  csv << "t_s,clearance_mm,temp_c,voltage_v\n";
  char line[160];
  for (std::size_t i = 0; i < s.size(); ++i) {
    std::snprintf(line, sizeof line, "%.4f,%.4f,%.1f,%.4f\n", s.t_s[i], s.clearance_mm[i],
                  s.temp_c[i], s.voltage_v[i]);
    csv << line;
  }
}

TEST(DiagnoseCommand, HeldOutDataMustBeAnotherSession) {
  const auto dir = fresh_test_dir("diagnose_same_session");
  const RecordingSeries a = room_temperature_session(1.0, 3, 600.0);
  write_csv(dir / "a.csv", a);
  write_csv(dir / "copy.csv", a);
  write_csv(dir / "middle.csv", slice_recording_series(a, 1000, 2500, "middle"));
  write_csv(dir / "b.csv", room_temperature_session(1.0, 4, 600.0));
  const std::string out = (dir / "out").string();
  const auto run = [&](const std::vector<std::string>& extra) {
    std::vector<std::string> args = {"diagnose", "--real", (dir / "a.csv").string(), "--out",
                                     out, "--bootstrap", "20"};
    args.insert(args.end(), extra.begin(), extra.end());
    return run_flange_captured(args);
  };
  struct Bad {
    std::vector<std::string> args;
    std::string expected;
  };
  const std::vector<Bad> cases = {
      {{"--holdout", (dir / "a.csv").string()}, "is the same recording as --real"},
      {{"--holdout", (dir / "copy.csv").string()}, "is the same recording as --real"},
      {{"--holdout", (dir / "middle.csv").string()}, "repeat rows of"},
      {{"--holdout", (dir / "b.csv").string(), "--real-start", "2026-11-21T09:30:00Z",
        "--holdout-start", "2026-11-21T09:35:00Z"},
       "must not overlap the calibration session in time"},
  };
  for (const Bad& bad : cases) {
    const FlangeOutcome o = run(bad.args);
    EXPECT_EQ(o.status, 2) << bad.expected << ": " << o.err;
    EXPECT_NE(o.err.find(bad.expected), std::string::npos) << o.err;
    EXPECT_EQ(std::count(o.err.begin(), o.err.end(), '\n'), 1) << o.err;
  }
  const FlangeOutcome later = run({"--holdout", (dir / "b.csv").string(), "--real-start",
                                   "2026-11-21T09:30:00Z", "--holdout-start",
                                   "2026-11-21T09:45:00Z"});
  EXPECT_EQ(later.status, 0) << later.err;
}

TEST(DiagnoseCommand, OneOperatingPointPrintsOnlyTheResults) {
  const auto dir = fresh_test_dir("diagnose_one_point");
  write_csv(dir / "still.csv", one_operating_point(-1.56, 600.0));
  ::testing::internal::CaptureStdout();
  const FlangeOutcome o = run_flange_captured({"diagnose", "--real", (dir / "still.csv").string(),
                                               "--holdout-fraction", "0.3", "--out",
                                               (dir / "out").string(), "--bootstrap", "20"});
  const std::string process_stdout = ::testing::internal::GetCapturedStdout();
  ASSERT_EQ(o.status, 0) << o.err;
  EXPECT_EQ(process_stdout.find("Warning"), std::string::npos) << process_stdout;
  EXPECT_NE(o.out.find("these data cannot tell them apart"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("  data: the clearance is constant"), std::string::npos) << o.out;
  EXPECT_EQ(o.out.find(" band "), std::string::npos) << o.out;
  std::ifstream in(dir / "out" / "diagnosis.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_FALSE(j["degenerate"].empty());
  EXPECT_FALSE(j["next_measurement"].empty());
  EXPECT_FALSE(j["effects"][0]["indistinguishable_from"].empty());
  EXPECT_FALSE(j["effects"][0]["undetermined"].empty());
}

}  // namespace
}  // namespace flange::diagnose

