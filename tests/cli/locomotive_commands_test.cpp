// SPDX-License-Identifier: MIT
// A whole locomotive as a user makes and runs it: `flange simulate --scenario loco --wheels N`
// (one wheel is today's recording byte for byte; twelve are reproducible, each with its own
// noise) and `flange run --manifest` (every channel's results equal to running its file alone).
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "flange_in_process.h"
#include "test_files.h"

namespace flange::cli {
namespace {

namespace fs = std::filesystem;
using testing::FlangeOutcome;
using testing::fresh_test_dir;
using testing::command_text;
using testing::run_flange_captured;

std::string read(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Runs flange and expects exit status 0; its stdout.
std::string flange_ok(const std::vector<std::string>& args) {
  const FlangeOutcome outcome = run_flange_captured(args);
  EXPECT_EQ(outcome.status, 0) << command_text(args) << "\n" << outcome.err;
  return outcome.out;
}

// Column `column` (0-based) of every data row of a CSV.
std::vector<std::string> column_of(const std::string& csv, int column) {
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> values;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string field;
    for (int k = 0; k <= column; ++k) std::getline(fields, field, ',');
    values.push_back(field);
  }
  return values;
}

std::string channel_csv(int channel) { return fmt::format("channel_{:02d}.csv", channel); }

const std::string kMeasurement =
    std::string(FLANGE_SOURCE_DIR) + "/coeffs/measurement_sos/filter.json";

// A calibration from a simulated bench session, made once for all tests.
class LocomotiveCommands : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = fresh_test_dir("locomotive_commands_" + std::to_string(::getpid()));
    flange_ok({"simulate", "--scenario", "bench", "--seed", "5", "--out", path("bench.csv")});
    flange_ok({"calibrate", "--data", path("bench.csv"), "--out", path("model.json")});
  }
  static void TearDownTestSuite() {
    if (!::testing::Test::HasFailure()) fs::remove_all(dir_);
  }
  static std::string path(const std::string& name) { return (dir_ / name).string(); }
  static fs::path dir_;
};
fs::path LocomotiveCommands::dir_;

TEST_F(LocomotiveCommands, OneWheelIsTodaysRecordingByteForByte) {
  // tests/data/loco_single_wheel_seed11.csv was written by the single-wheel `flange simulate`
  // before the locomotive existed (commit 4a4d4a3) with exactly these arguments.
  const std::string golden =
      read(fs::path(FLANGE_SOURCE_DIR) / "tests/data/loco_single_wheel_seed11.csv");
  ASSERT_FALSE(golden.empty());
  const std::vector<std::string> args = {"simulate", "--scenario", "loco",     "--seed",
                                         "11",       "--fs",       "10",       "--duration",
                                         "30",       "--effect",   "vibration"};
  std::vector<std::string> plain = args;
  plain.insert(plain.end(), {"--out", path("plain.csv")});
  std::vector<std::string> one = args;
  one.insert(one.end(), {"--wheels", "1", "--out", path("one.csv")});
  std::vector<std::string> twelve = args;
  twelve.insert(twelve.end(), {"--wheels", "12", "--out", path("twelve")});
  flange_ok(plain);
  flange_ok(one);
  flange_ok(twelve);
  EXPECT_EQ(read(path("plain.csv")), golden);
  EXPECT_EQ(read(path("one.csv")), golden);
  EXPECT_EQ(read(dir_ / "twelve" / channel_csv(0)), golden);  // channel 0 is that wheel
}

TEST_F(LocomotiveCommands, TwelveWheelsAreReproducibleAndEachHasItsOwnNoise) {
  const auto simulate = [&](const std::string& seed, const std::string& folder) {
    const std::string out =
        flange_ok({"simulate", "--scenario", "loco", "--wheels", "12", "--fs", "20", "--duration",
                   "60", "--seed", seed, "--out", path(folder)});
    EXPECT_NE(out.find("wrote " + path(folder) + "/locomotive.json and 12 recordings"),
              std::string::npos)
        << out;
  };
  simulate("4", "a");
  simulate("4", "b");
  simulate("5", "c");
  const nlohmann::json manifest = nlohmann::json::parse(read(dir_ / "a" / "locomotive.json"));
  ASSERT_EQ(manifest["channels"].size(), 12u);
  std::set<std::string> voltages;
  for (int c = 0; c < 12; ++c) {
    const nlohmann::json& entry = manifest["channels"][static_cast<std::size_t>(c)];
    EXPECT_EQ(entry["channel"], c);
    EXPECT_EQ(entry["axle"], c / 2 + 1);
    EXPECT_EQ(entry["side"], c % 2 == 0 ? "left" : "right");
    EXPECT_EQ(entry["file"], channel_csv(c));
    const std::string a = read(dir_ / "a" / channel_csv(c));
    const std::string c_seed = read(dir_ / "c" / channel_csv(c));
    EXPECT_EQ(a, read(dir_ / "b" / channel_csv(c))) << "channel " << c << ": same seed";
    EXPECT_NE(a, c_seed) << "channel " << c << ": another seed";
    // Another seed is another measurement of the same locomotive: the truth stays.
    EXPECT_EQ(column_of(a, 1), column_of(c_seed, 1)) << "channel " << c;
    const std::vector<std::string> v = column_of(a, 3);
    std::string joined;
    for (const std::string& value : v) joined += value + ",";
    voltages.insert(joined);
  }
  EXPECT_EQ(voltages.size(), 12u);  // every wheel its own sensor and noise
}

// Reads the single-recording run's output CSV: its last filtered clearance and the extremes
// after `settle` rows.
struct FilteredColumn {
  double last = 0.0, min = 1e9, max = -1e9;
};
FilteredColumn filtered_column(const std::string& csv, std::uint64_t settle) {
  FilteredColumn f;
  const std::vector<std::string> values = column_of(csv, 2);
  for (std::size_t k = 0; k < values.size(); ++k) {
    f.last = std::stod(values[k]);
    if (k < settle) continue;
    f.min = std::min(f.min, f.last);
    f.max = std::max(f.max, f.last);
  }
  return f;
}

TEST_F(LocomotiveCommands, TwelveWheelsRunEndToEndAsEachChannelAlone) {
  // 300 s at 6 Hz: 1801 samples per wheel, five laps, past the warning level.
  flange_ok({"simulate", "--scenario", "loco", "--wheels", "12", "--fs", "6", "--seed", "2",
             "--out", path("loco")});
  const std::string table =
      flange_ok({"run", "--manifest", path("loco/locomotive.json"), "--calibration",
                 path("model.json"), "--coeffs", kMeasurement, "--out", path("loco_run")});
  EXPECT_NE(table.find("12 channel(s)"), std::string::npos) << table;
  EXPECT_NE(table.find("worst wheel: channel"), std::string::npos) << table;
  for (const char* file : {"summary.json", "index.html", "clearance.svg", "channel_11/index.html",
                           "channel_00/traces.svg"}) {
    EXPECT_TRUE(fs::exists(dir_ / "loco_run" / file)) << file;
  }
  const nlohmann::json summary = nlohmann::json::parse(read(dir_ / "loco_run" / "summary.json"));
  ASSERT_EQ(summary["channels"].size(), 12u);
  for (int c = 0; c < 12; ++c) {
    const nlohmann::json& s = summary["channels"][static_cast<std::size_t>(c)];
    const std::string alone_csv = path(fmt::format("alone_{:02d}.csv", c));
    const std::string alone =
        flange_ok({"run", "--input", path("loco/" + channel_csv(c)), "--calibration",
                   path("model.json"), "--coeffs", kMeasurement, "--out", alone_csv});
    // The output CSV, row for row and byte for byte.
    const std::string output = read(dir_ / "loco_run" / channel_csv(c));
    EXPECT_EQ(output, read(alone_csv)) << "channel " << c;
    // The summary's figures, from the run alone.
    EXPECT_NE(alone.find(fmt::format("rows read {}, flagged {}", s["rows_read"].get<int>(),
                                     s["rows_flagged"].get<int>())),
              std::string::npos)
        << "channel " << c << "\n"
        << alone;
    EXPECT_NE(alone.find(fmt::format("alarm events {}, final level {}", s["alarm_events"].size(),
                                     s["final_alarm"].get<std::string>())),
              std::string::npos)
        << "channel " << c << "\n"
        << alone;
    // The run alone prints its first ten events.
    for (std::size_t k = 0; k < s["alarm_events"].size() && k < 10; ++k) {
      const nlohmann::json& event = s["alarm_events"][k];
      const std::string line = fmt::format("t = {:.2f} s: {}", event["t_s"].get<double>(),
                                           event["what"].get<std::string>());
      EXPECT_NE(alone.find(line), std::string::npos) << "channel " << c << ": " << line;
    }
    const FilteredColumn f =
        filtered_column(read(alone_csv), s["settle_samples"].get<std::uint64_t>());
    EXPECT_NEAR(s["final_filtered_mm"].get<double>(), f.last, 5e-7) << "channel " << c;
    EXPECT_NEAR(s["min_filtered_mm"].get<double>(), f.min, 5e-7) << "channel " << c;
    EXPECT_NEAR(s["max_filtered_mm"].get<double>(), f.max, 5e-7) << "channel " << c;
  }
}

TEST_F(LocomotiveCommands, AMultichannelCoreFiltersEachWheelOnItsOwnChannel) {
  // Three wheels on a core with a coefficient set per channel: channel c's output is that of
  // `run --channel c` on its file, and the channels' different filters give different outputs.
  const std::string sets = std::string(FLANGE_SOURCE_DIR) + "/tests/data/coeffs/loco_sets3/filter.json";
  flange_ok({"simulate", "--scenario", "loco", "--wheels", "3", "--fs", "100", "--duration",
             "20", "--seed", "4", "--out", path("three")});
  flange_ok({"run", "--manifest", path("three/locomotive.json"), "--calibration",
             path("model.json"), "--coeffs", sets, "--engine", "rtl", "--out", path("three_run")});
  for (int c = 0; c < 3; ++c) {
    const std::string alone_csv = path(fmt::format("three_alone_{}.csv", c));
    flange_ok({"run", "--input", path("three/" + channel_csv(c)), "--channel",
               std::to_string(c), "--calibration", path("model.json"), "--coeffs", sets,
               "--out", alone_csv});
    EXPECT_EQ(read(dir_ / "three_run" / channel_csv(c)), read(alone_csv)) << "channel " << c;
  }
  // Channel 1's file through channel 0's filter differs from its own channel's result.
  const std::string on_zero = path("three_on_zero.csv");
  flange_ok({"run", "--input", path("three/" + channel_csv(1)), "--channel", "0", "--calibration",
             path("model.json"), "--coeffs", sets, "--out", on_zero});
  EXPECT_NE(read(on_zero), read(dir_ / "three_run" / channel_csv(1)));
  // More wheels than the core has channels: refused, one line.
  flange_ok({"simulate", "--scenario", "loco", "--wheels", "4", "--fs", "100", "--duration", "2",
             "--seed", "4", "--out", path("four")});
  const FlangeOutcome refused =
      run_flange_captured({"run", "--manifest", path("four/locomotive.json"), "--calibration",
                           path("model.json"), "--coeffs", sets});
  EXPECT_EQ(refused.status, 2);
  EXPECT_NE(refused.err.find("has channels 0 to 2 only"), std::string::npos) << refused.err;
}

TEST_F(LocomotiveCommands, AManifestRunRefusesToOverwriteItsInputs) {
  flange_ok({"simulate", "--scenario", "loco", "--wheels", "2", "--fs", "6", "--duration", "60",
             "--seed", "1", "--out", path("pair")});
  const std::string before = read(dir_ / "pair" / channel_csv(1));
  const FlangeOutcome outcome =
      run_flange_captured({"run", "--manifest", path("pair/locomotive.json"), "--calibration",
                           path("model.json"), "--coeffs", kMeasurement, "--out", path("pair")});
  EXPECT_EQ(outcome.status, 2) << outcome.err;
  EXPECT_NE(outcome.err.find("would overwrite channel 0's input"), std::string::npos)
      << outcome.err;
  EXPECT_EQ(read(dir_ / "pair" / channel_csv(1)), before);
}

TEST_F(LocomotiveCommands, AWheelsOwnCalibrationFromTheManifestReplacesTheFallback) {
  // Wheel 1's manifest entry names its own calibration (from another bench session): its output is
  // that of `run --input` with that calibration; wheel 0 names none and falls back to
  // --calibration. A calibration that does not exist is refused with the field's name.
  flange_ok({"simulate", "--scenario", "bench", "--seed", "9", "--out", path("bench9.csv")});
  flange_ok({"calibrate", "--data", path("bench9.csv"), "--out", path("model9.json")});
  flange_ok({"simulate", "--scenario", "loco", "--wheels", "2", "--fs", "6", "--duration", "60",
             "--seed", "3", "--out", path("own")});
  nlohmann::json manifest = nlohmann::json::parse(read(dir_ / "own" / "locomotive.json"));
  manifest["channels"][1]["calibration"] = "../model9.json";
  std::ofstream(dir_ / "own" / "locomotive.json") << manifest.dump(2);
  flange_ok({"run", "--manifest", path("own/locomotive.json"), "--calibration",
             path("model.json"), "--coeffs", kMeasurement, "--out", path("own_run")});
  for (const auto& [c, model] : {std::pair{0, "model.json"}, std::pair{1, "model9.json"}}) {
    const std::string alone_csv = path(fmt::format("own_alone_{}.csv", c));
    flange_ok({"run", "--input", path("own/" + channel_csv(c)), "--calibration", path(model),
               "--coeffs", kMeasurement, "--out", alone_csv});
    EXPECT_EQ(read(dir_ / "own_run" / channel_csv(c)), read(alone_csv)) << "channel " << c;
  }
  const std::string with_fallback = path("own_fallback.csv");
  flange_ok({"run", "--input", path("own/" + channel_csv(1)), "--calibration",
             path("model.json"), "--coeffs", kMeasurement, "--out", with_fallback});
  EXPECT_NE(read(with_fallback), read(dir_ / "own_run" / channel_csv(1)))
      << "the two calibrations should give different clearances";

  manifest["channels"][0]["calibration"] = "missing.json";
  std::ofstream(dir_ / "own" / "locomotive.json") << manifest.dump(2);
  const FlangeOutcome refused =
      run_flange_captured({"run", "--manifest", path("own/locomotive.json"), "--calibration",
                           path("model.json"), "--coeffs", kMeasurement});
  EXPECT_EQ(refused.status, 2);
  EXPECT_NE(refused.err.find("field channels[0].calibration: "), std::string::npos)
      << refused.err;
  EXPECT_NE(refused.err.find("missing.json does not exist"), std::string::npos) << refused.err;
}

}  // namespace
}  // namespace flange::cli
