// SPDX-License-Identifier: MIT
// `flange simulate` as a user runs it: the recording's format, reproducibility by seed, the twin
// file options, and one-line errors with exit status 2 for every bad argument.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <utility>

#include "cli.h"
#include "flange_in_process.h"

namespace flange::cli {
namespace {

using testing::FlangeOutcome;
using testing::run_flange_captured;

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::path(FLANGE_BINARY_DIR) / "test_simulate_command";
  fs::create_directories(dir);
  fs::remove(dir / name);
  return dir / name;
}

std::string read(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Runs simulate into a fresh file and returns the file's bytes.
std::string simulate(const std::vector<std::string>& args, const std::string& file) {
  const fs::path out = scratch(file);
  std::vector<std::string> full = {"simulate"};
  full.insert(full.end(), args.begin(), args.end());
  full.push_back("--out");
  full.push_back(out.string());
  const FlangeOutcome outcome = run_flange_captured(full);
  EXPECT_EQ(outcome.status, 0) << outcome.err;
  EXPECT_TRUE(outcome.err.empty()) << outcome.err;
  return read(out);
}

std::vector<std::vector<double>> rows_of(const std::string& csv) {
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::istringstream fields(line);
    std::string field;
    while (std::getline(fields, field, ',')) row.push_back(std::stod(field));
    rows.push_back(row);
  }
  return rows;
}

void expect_recording(const std::string& csv, std::size_t expected_rows, double fs_hz) {
  ASSERT_EQ(csv.substr(0, csv.find('\n')), "t_s,clearance_mm,temp_c,voltage_v");
  const std::vector<std::vector<double>> rows = rows_of(csv);
  ASSERT_EQ(rows.size(), expected_rows);
  for (std::size_t n = 0; n < rows.size(); ++n) {
    ASSERT_EQ(rows[n].size(), 4u) << n;
    ASSERT_NEAR(rows[n][0], static_cast<double>(n) / fs_hz, 1e-6) << n;
    if (n > 0) {
      ASSERT_GT(rows[n][0], rows[n - 1][0]) << n;
    }
    ASSERT_GE(rows[n][3], -1.0) << n;
    ASSERT_LE(rows[n][3], 11.0) << n;
  }
}

TEST(SimulateCommand, BenchWritesTheRecordingFormatAtSixHertz) {
  const std::string csv =
      simulate({"--scenario", "bench", "--seed", "1", "--duration", "600"}, "bench.csv");
  expect_recording(csv, 3601, 6.0);
  const std::vector<std::vector<double>> rows = rows_of(csv);
  EXPECT_DOUBLE_EQ(rows[0][1], 1.5);
  EXPECT_DOUBLE_EQ(rows[0][2], 20.0);
  EXPECT_NEAR(rows[0][3], 0.9, 0.35);  // eq. 3.14 at 1.5 mm, 20 degC: 0.89 V, plus noise
}

TEST(SimulateCommand, LocoWritesTheRecordingFormatAtAHundredHertz) {
  const std::string csv =
      simulate({"--scenario", "loco", "--seed", "1", "--duration", "30"}, "loco.csv");
  expect_recording(csv, 3001, 100.0);
}

TEST(SimulateCommand, SameSeedSameBytesOtherSeedOtherBytes) {
  for (const std::string scenario : {"bench", "loco"}) {
    const std::vector<std::string> args = {
        "--scenario", scenario,    "--duration", "60",
        "--effect",   "vibration", "--effect",   "mains_pickup:amplitude_v=0.05"};
    std::vector<std::string> seed_3 = args;
    seed_3.insert(seed_3.end(), {"--seed", "3"});
    std::vector<std::string> seed_4 = args;
    seed_4.insert(seed_4.end(), {"--seed", "4"});
    const std::string first = simulate(seed_3, scenario + "_a.csv");
    const std::string again = simulate(seed_3, scenario + "_b.csv");
    const std::string other = simulate(seed_4, scenario + "_c.csv");
    EXPECT_EQ(first, again) << scenario;
    EXPECT_NE(first, other) << scenario;
    // Another seed changes the measured channels, never the reference.
    const auto a = rows_of(first);
    const auto c = rows_of(other);
    for (std::size_t n = 0; n < a.size(); ++n) ASSERT_EQ(a[n][1], c[n][1]) << scenario << n;
  }
}

TEST(SimulateCommand, SavedTwinReproducesTheRunAndCanBeRetuned) {
  const fs::path twin = scratch("twin.json");
  const std::string direct = simulate(
      {"--scenario", "bench", "--seed", "9", "--duration", "120", "--effect",
       "thermal_lag:tau_s=-40", "--effect", "adc_quantization", "--save-twin", twin.string()},
      "direct.csv");
  ASSERT_TRUE(fs::exists(twin));
  const std::string from_file =
      simulate({"--scenario", "bench", "--seed", "9", "--duration", "120", "--twin", twin.string()},
               "from_file.csv");
  EXPECT_EQ(direct, from_file);
  // A key given on the command line retunes the file's effect; its other keys are kept.
  const fs::path retuned = scratch("retuned.json");
  simulate({"--scenario", "bench", "--seed", "9", "--duration", "12", "--twin", twin.string(),
            "--effect", "adc_quantization:bits=8", "--save-twin", retuned.string()},
           "retuned.csv");
  const std::string saved = read(retuned);
  EXPECT_NE(saved.find("\"bits\": 8.0"), std::string::npos) << saved;
  EXPECT_NE(saved.find("\"tau_s\": -40.0"), std::string::npos) << saved;
}

TEST(SimulateCommand, SummaryReportsAliasingOfMainsAndTheLateralMode) {
  const fs::path out = scratch("summary.csv");
  const FlangeOutcome outcome =
      run_flange_captured({"simulate", "--scenario", "loco", "--fs", "6", "--duration", "10",
                           "--seed", "1", "--effect", "mains_pickup", "--out", out.string()});
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  EXPECT_NE(outcome.out.find("tones at 50, 100, 150 Hz appear at 2, 2, 0 Hz"), std::string::npos)
      << outcome.out;
  EXPECT_NE(outcome.out.find("lateral mode: 6.39 Hz"), std::string::npos) << outcome.out;
  EXPECT_NE(outcome.out.find("appears at 0.387 Hz"), std::string::npos) << outcome.out;
}

TEST(SimulateCommand, SamplesOnTheRailsAreCountedInTheSummary) {
  const auto rail_counts = [](const std::vector<std::string>& effect) {
    const fs::path out = scratch("rails.csv");
    std::vector<std::string> args = {"simulate", "--scenario", "bench",     "--seed",
                                     "1",        "--out",      out.string()};
    args.insert(args.end(), effect.begin(), effect.end());
    const FlangeOutcome outcome = run_flange_captured(args);
    EXPECT_EQ(outcome.status, 0) << outcome.err;
    const std::smatch match = [&] {
      std::smatch m;
      std::regex_search(outcome.out, m, std::regex(R"(rail: (\d+) samples at 0 V, (\d+) at 10 V)"));
      return m;
    }();
    EXPECT_EQ(match.size(), 3u) << outcome.out;
    return std::pair<long, long>{std::stol(match[1]), std::stol(match[2])};
  };
  EXPECT_EQ(rail_counts({}), (std::pair<long, long>{0, 0}));
  // A strong positive gain drift drives the hot sensor onto its top rail at large clearances.
  const auto [low, high] = rail_counts({"--effect", "temp_gain_drift:gain_per_c=0.01"});
  EXPECT_EQ(low, 0);
  EXPECT_GT(high, 1000);
  // A strong negative offset drift drives it onto the bottom rail at small clearances.
  const auto [low_offset, high_offset] =
      rail_counts({"--effect", "temp_offset_drift:offset_v_per_c=-0.05"});
  EXPECT_GT(low_offset, 1000);
  EXPECT_EQ(high_offset, 0);
}

struct BadInput {
  std::vector<std::string> args;
  std::string names;  // what the one-line message must name
};

TEST(SimulateCommand, EveryBadArgumentExitsTwoWithOneLineAndNoRecording) {
  const fs::path out = scratch("never.csv");
  const fs::path bad_twin = scratch("bad_twin.json");
  std::ofstream(bad_twin) << R"({"effects": [{"name": "vibration", "params": {"rms_mm": 9}}]})";
  const std::vector<BadInput> cases = {
      {{"--scenario", "tram", "--seed", "1"}, "--scenario"},
      {{"--scenario", "bench"}, "--seed"},
      {{"--scenario", "bench", "--seed", "-1"}, "--seed"},
      {{"--scenario", "bench", "--seed", "x"}, "--seed"},
      {{"--seed", "1"}, "--scenario"},
      {{"--scenario", "bench", "--seed", "1", "--fs", "0"}, "--fs"},
      {{"--scenario", "bench", "--seed", "1", "--fs", "-6"}, "--fs"},
      {{"--scenario", "bench", "--seed", "1", "--fs", "nan"}, "--fs"},
      {{"--scenario", "bench", "--seed", "1", "--fs", "inf"}, "--fs"},
      {{"--scenario", "bench", "--seed", "1", "--fs", "1e6"}, "(0, 100000] Hz"},
      {{"--scenario", "bench", "--seed", "1", "--fs", "six"}, "--fs"},
      {{"--scenario", "loco", "--seed", "1", "--duration", "0"}, "--duration"},
      {{"--scenario", "loco", "--seed", "1", "--duration", "-5"}, "--duration"},
      {{"--scenario", "loco", "--seed", "1", "--duration", "nan"}, "--duration"},
      {{"--scenario", "loco", "--seed", "1", "--fs", "100000", "--duration", "31622400"},
       "--fs x --duration"},
      {{"--scenario", "bench", "--seed", "1", "--effect", "hum"}, "unknown effect 'hum'"},
      {{"--scenario", "bench", "--seed", "1", "--effect", "mains_pickup:amplitude_v"},
       "--effect 'mains_pickup:amplitude_v'"},
      {{"--scenario", "bench", "--seed", "1", "--effect", "mains_pickup:=1"}, "--effect"},
      {{"--scenario", "bench", "--seed", "1", "--effect", ":x=1"}, "--effect"},
      {{"--scenario", "bench", "--seed", "1", "--effect", "mains_pickup:amplitude_v=loud"},
       "amplitude_v"},
      {{"--scenario", "bench", "--seed", "1", "--effect", "mains_pickup:amp=1"},
       "unknown key 'amp'"},
      {{"--scenario", "bench", "--seed", "1", "--effect", "mains_pickup:amplitude_v=2"},
       "amplitude_v = 2 is outside its valid range [0, 1] V"},
      {{"--scenario", "bench", "--seed", "1", "--effect", "mains_pickup:amplitude_v=nan"},
       "amplitude_v = nan"},
      {{"--scenario", "bench", "--seed", "1", "--effect", "adc_quantization:bits=10.5"},
       "bits = 10.5"},
      {{"--scenario", "bench", "--seed", "1", "--effect", "vibration:f_low_hz=50,f_high_hz=5"},
       "f_low_hz must be below f_high_hz"},
      {{"--scenario", "bench", "--seed", "1", "--effect", "vibration", "--effect", "vibration"},
       "given twice"},
      {{"--scenario", "bench", "--seed", "1", "--twin", bad_twin.string()},
       "effects[0]: rms_mm = 9"},
      {{"--scenario", "bench", "--seed", "1", "--twin", scratch("missing.json").string()},
       "missing.json"},
      {{"--scenario", "loco", "--seed", "1", "--wheels", "0"}, "--wheels: 0 is outside"},
      {{"--scenario", "loco", "--seed", "1", "--wheels", "13"}, "a whole number 1 to 12"},
      {{"--scenario", "loco", "--seed", "1", "--wheels", "2.5"}, "--wheels: 2.5 is outside"},
      {{"--scenario", "loco", "--seed", "1", "--wheels", "two"}, "--wheels: two is outside"},
      {{"--scenario", "bench", "--seed", "1", "--wheels", "2"},
       "--wheels: only the loco scenario has wheels"},
      {{"--scenario", "loco", "--seed", "1", "--wheels", "3", "--fs", "0"}, "--fs"},
  };
  for (const BadInput& input : cases) {
    fs::remove(out);
    std::vector<std::string> args = {"simulate"};
    args.insert(args.end(), input.args.begin(), input.args.end());
    args.push_back("--out");
    args.push_back(out.string());
    const FlangeOutcome outcome = run_flange_captured(args);
    std::string command;
    for (const std::string& word : args) command += " " + word;
    EXPECT_EQ(outcome.status, 2) << "flange" << command;
    EXPECT_EQ(std::count(outcome.err.begin(), outcome.err.end(), '\n'), 1)
        << "flange" << command << "\n"
        << outcome.err;
    EXPECT_NE(outcome.err.find(input.names), std::string::npos) << "flange" << command << "\n"
                                                                << outcome.err;
    EXPECT_FALSE(fs::exists(out)) << "flange" << command;
  }
}

}  // namespace
}  // namespace flange::cli
