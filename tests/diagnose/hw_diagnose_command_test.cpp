// SPDX-License-Identifier: MIT
// `flange diagnose --hw`: on the measurement filter the gap to the Verilated RTL is explained down
// to zero with the RTL agreeing word for word; the thesis's printed eq. 4.20 coefficients are
// reported unstable by coefficient rounding; bad input exits 2 with one line naming the option or
// file and field. The first run builds the set's RTL runner (cached in build/cosim_cache).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "cli.h"
#include "flange_in_process.h"
#include "test_files.h"

namespace flange::diagnose {
namespace {

using testing::FlangeOutcome;
using testing::run_flange_captured;
namespace fs = std::filesystem;

const fs::path kCoeffs = fs::path(FLANGE_SOURCE_DIR) / "coeffs";

std::string last_line(const std::string& text) {
  std::string t = text;
  while (!t.empty() && t.back() == '\n') t.pop_back();
  return t.substr(t.rfind('\n') == std::string::npos ? 0 : t.rfind('\n') + 1);
}

TEST(HwDiagnoseCommand, MeasurementFilterGapExplainedToZeroAndRtlAgrees) {
  const fs::path dir = testing::fresh_test_dir("hw_diagnose_measurement");
  const std::string json = (kCoeffs / "measurement_sos" / "filter.json").string();
  const FlangeOutcome r =
      run_flange_captured({"diagnose", "--hw", "--coeffs", json, "--stimulus", "sweep", "--samples",
                           "3000", "--out", dir.string()});
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_TRUE(std::regex_match(
      last_line(r.out),
      std::regex("diagnose --hw: gap [0-9.e+-]+ LSB RMS explained down to 0 in 6 steps; staged = "
                 "model = RTL on 3000 of 3000 samples \\(runner: 0 mismatches\\)")))
      << r.out;

  std::ifstream in(dir / "hw_diagnosis.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j["model_vs_rtl_mismatches"], 0);
  EXPECT_EQ(j["staged_vs_model_mismatches"], 0);
  const auto& steps = j["steps"];
  ASSERT_EQ(steps.size(), 7u) << "the float design, then one step per effect";
  EXPECT_EQ(steps[0]["effect_added"], "none");
  EXPECT_GT(steps[0]["gap_rms_lsb"].get<double>(), 0.1) << "the float design is not the hardware";
  EXPECT_EQ(steps.back()["gap_rms_lsb"].get<double>(), 0.0);
  EXPECT_EQ(steps.back()["samples_differing"], 0);
  EXPECT_EQ(steps.back()["effects_on"].size(), 6u);
  // Greedy: every step leaves the least gap among the effects still to add, so the effects are
  // each added once.
  std::vector<std::string> added;
  for (std::size_t i = 1; i < steps.size(); ++i) added.push_back(steps[i]["effect_added"]);
  std::sort(added.begin(), added.end());
  EXPECT_EQ(std::adjacent_find(added.begin(), added.end()), added.end());
  EXPECT_EQ(j["unstable_step"], nullptr);
  for (const char* f : {"hw_diagnosis.html", "gap_steps.svg", "traces.svg"}) {
    EXPECT_GT(fs::file_size(dir / f), 500u) << f;
  }
}

TEST(HwDiagnoseCommand, ThesisEq420PrintedCoefficientsAreUnstableByCoefficientRounding) {
  const std::string json = (kCoeffs / "vehicle_sos" / "filter.json").string();
  const FlangeOutcome r =
      run_flange_captured({"diagnose", "--hw", "--coeffs", json, "--thesis-eq-4-20", "--stimulus",
                           "step", "--samples", "2000"});
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  const std::string line = last_line(r.out);
  EXPECT_NE(line.find("coefficient rounding to the printed values (eq. 4.20 as printed) alone "
                      "(step 1) makes the filter unstable: 3 pole(s) on or outside the unit "
                      "circle (max |z| = 1.7262)"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("UNSTABLE"), std::string::npos) << r.out;
}

TEST(HwDiagnoseCommand, StablePrintedCoefficientsAreSaidStable) {
  // The float design's own b/a rounded to 4 significant digits, for a well-conditioned filter.
  const std::string json = (kCoeffs / "measurement_sos" / "filter.json").string();
  const FlangeOutcome r =
      run_flange_captured({"diagnose", "--hw", "--coeffs", json, "--tf-b",
                           "0.001063,0.005317,0.01063,0.01063,0.005317,0.001063", "--tf-a",
                           "1,-3.062,3.998,-2.719,0.9549,-0.1376", "--samples", "500"});
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_NE(last_line(r.out).find("are stable"), std::string::npos) << r.out;
}

TEST(HwDiagnoseCommand, BadInputExitsTwoWithOneLine) {
  const fs::path dir = testing::fresh_test_dir("hw_diagnose_bad");
  const std::string good = (kCoeffs / "measurement_sos" / "filter.json").string();
  const fs::path bad_json =
      testing::write_file(dir / "filter.json", R"({"quantized": {"data_bits": "16"}})");
  const fs::path bad_csv = testing::write_file(dir / "stim.csv", "1.5\n2\n70000\n");
  struct Case {
    std::vector<std::string> args;
    std::string names;  // what the message must name
  };
  const std::vector<Case> cases = {
      {{"diagnose", "--hw"}, "--coeffs"},
      {{"diagnose", "--hw", "--coeffs", bad_json.string()}, "quantized.data_bits"},
      {{"diagnose", "--hw", "--coeffs", good, "--samples", "0"}, "--samples"},
      {{"diagnose", "--hw", "--coeffs", good, "--stimulus", "chirp"}, "--stimulus 'chirp'"},
      {{"diagnose", "--hw", "--coeffs", good, "--stimulus", bad_csv.string()},
       bad_csv.string() + ":3: column 1"},
      {{"diagnose", "--hw", "--coeffs", good, "--thesis-eq-4-20"}, "vehicle_sos"},
      {{"diagnose", "--hw", "--coeffs", good, "--tf-b", "1,2"}, "--tf-b --tf-a"},
      {{"diagnose", "--coeffs", good}, "--hw"},
  };
  for (const Case& c : cases) {
    const FlangeOutcome r = run_flange_captured(c.args);
    std::string joined;
    for (const std::string& a : c.args) joined += a + " ";
    EXPECT_EQ(r.status, 2) << joined << r.out << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << joined << r.err;
    EXPECT_NE(r.err.find(c.names), std::string::npos) << joined << ": " << r.err;
    EXPECT_TRUE(r.out.empty()) << joined << r.out;
  }
}

}  // namespace
}  // namespace flange::diagnose
