// SPDX-License-Identifier: MIT
// `flange calibrate --store` and `flange run --store` as a user runs them (SQLite; the store's
// own tests cover PostgreSQL): the refit from the store, a locomotive's wheels kept (each at its
// axle's clearance at reference conditions, which `flange wear` reads), two runs written at once
// by two processes, bad and unreachable stores.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "axle_clearance.h"
#include "flange_in_process.h"
#include "locomotive_run.h"
#include "store.h"
#include "test_files.h"

namespace flange::cli {
namespace {

namespace fs = std::filesystem;
using testing::FlangeOutcome;
using testing::fresh_test_dir;
using testing::run_flange_captured;

const std::string kMeasurement =
    std::string(FLANGE_SOURCE_DIR) + "/coeffs/measurement_sos/filter.json";

std::string flange_ok(const std::vector<std::string>& args) {
  const FlangeOutcome outcome = run_flange_captured(args);
  std::string text = "flange";
  for (const std::string& a : args) text += " " + a;
  EXPECT_EQ(outcome.status, 0) << text << "\n" << outcome.err;
  return outcome.out;
}

nlohmann::json coefficients(const fs::path& model) {
  return nlohmann::json::parse(std::ifstream(model))["coefficients"];
}

// Two bench sessions (one CSV database with a run column) and a 12-wheel run at 6 Hz.
class StoreCommands : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = fresh_test_dir("store_commands_" + std::to_string(::getpid()));
    flange_ok({"simulate", "--scenario", "bench", "--seed", "5", "--duration", "1200", "--out",
               path("a.csv")});
    flange_ok({"simulate", "--scenario", "bench", "--seed", "6", "--duration", "1200", "--out",
               path("b.csv")});
    flange_ok({"calibrate", "--data", path("db.csv"), "--append", path("a.csv"), "--out",
               path("model_a.json")});
    flange_ok({"calibrate", "--data", path("db.csv"), "--append", path("b.csv"), "--out",
               path("model_csv.json")});
    flange_ok({"simulate", "--scenario", "loco", "--wheels", "12", "--fs", "6", "--duration", "120",
               "--seed", "2", "--out", path("loco")});
  }
  static std::string path(const std::string& name) { return (dir_ / name).string(); }
  static fs::path dir_;
};
fs::path StoreCommands::dir_;

TEST_F(StoreCommands, CalibrateImportsTheCsvAndRefitsFromTheStoreAsFromTheCsv) {
  const std::string store = "sqlite:" + path("calibrate.db");
  const std::string out = flange_ok({"calibrate", "--data", path("db.csv"), "--store", store,
                                     "--sensor", "S-1", "--out", path("model_store.json")});
  EXPECT_NE(out.find("imported 2 bench sessions (2 new"), std::string::npos) << out;
  EXPECT_EQ(coefficients(path("model_store.json")), coefficients(path("model_csv.json")));
  // The same database again: nothing new, one more calibration kept.
  const std::string again = flange_ok(
      {"calibrate", "--data", path("db.csv"), "--store", store, "--out", path("model_again.json")});
  EXPECT_NE(again.find("(0 new"), std::string::npos) << again;
  auto opened = host::open_store(store);
  EXPECT_EQ(opened->sessions(host::SessionKind::kBench).size(), 2u);
  const auto calibrations = opened->calibrations();
  ASSERT_EQ(calibrations.size(), 2u);
  EXPECT_EQ(calibrations[0].second.session_ids.size(), 2u);
  EXPECT_EQ(calibrations[0].second.sensor_serial, "S-1");
}

TEST_F(StoreCommands, AppendingToTheStoreAloneRefitsFromEverySession) {
  const std::string store = "sqlite:" + path("append.db");
  flange_ok({"calibrate", "--store", store, "--append", path("a.csv"), "--out", path("m1.json")});
  EXPECT_EQ(coefficients(path("m1.json")), coefficients(path("model_a.json")));
  flange_ok({"calibrate", "--store", store, "--append", path("b.csv"), "--out", path("m2.json")});
  EXPECT_EQ(coefficients(path("m2.json")), coefficients(path("model_csv.json")));
}

TEST_F(StoreCommands, RunKeepsEveryWheelOfALocomotive) {
  const std::string store = "sqlite:" + path("run.db");
  const std::string out = flange_ok(
      {"run", "--manifest", path("loco/locomotive.json"), "--calibration", path("model_csv.json"),
       "--coeffs", kMeasurement, "--store", store, "--locomotive", "G-1; 'x'", "--started-at",
       "2026-03-01T06:00:00Z", "--distance-km", "3", "--odometer-km", "1003"});
  EXPECT_NE(out.find("stored as run 1 in " + store), std::string::npos) << out;
  auto opened = host::open_store(store);
  EXPECT_EQ(opened->wheels().size(), 12u);
  const auto history = opened->wear_history({"G-1; 'x'", 6, "right"});
  ASSERT_EQ(history.size(), 1u);
  EXPECT_EQ(history[0].started_at, "2026-03-01T06:00:00.000Z");
  EXPECT_DOUBLE_EQ(history[0].odometer_km, 1003.0);
  EXPECT_TRUE(history[0].clearance_mm.has_value());
  const auto trace = opened->run_trace(history[0].run_id);
  EXPECT_EQ(trace.size(), 36u);  // 12 wheels x 3 km
}

// One axle's settled samples straight from the chain: the rows past the filter's start-up.
host::WheelSamples settled(const host::ChannelRun& channel) {
  const double settle_s =
      static_cast<double>(channel.summary.settle_samples) / channel.summary.fs_hz;
  host::WheelSamples samples;
  for (std::size_t k = 0; k < channel.trace.t_s.size(); ++k) {
    if (channel.trace.t_s[k] < settle_s) continue;
    samples.clearance_mm.push_back(channel.trace.filt_mm[k]);
    samples.temp_c.push_back(channel.trace.temp_c[k]);
  }
  return samples;
}

TEST_F(StoreCommands, RunKeepsEachWheelAtItsAxlesClearanceAtReferenceConditions) {
  const std::string store = "sqlite:" + path("axle.db");
  flange_ok({"run", "--manifest", path("loco/locomotive.json"), "--calibration",
             path("model_csv.json"), "--coeffs", kMeasurement, "--store", store, "--locomotive",
             "A-1", "--started-at", "2026-03-01T06:00:00Z", "--odometer-km", "1000"});
  host::RunOptions options;
  options.calibration = path("model_csv.json");
  options.coeffs = kMeasurement;
  const host::LocomotiveRun run = host::run_locomotive(
      host::load_locomotive_manifest(path("loco/locomotive.json")), options, std::nullopt, true);
  ASSERT_EQ(run.channels.size(), 12u);
  auto opened = host::open_store(store);
  for (std::size_t k = 0; k < run.channels.size(); k += 2) {
    const host::ManifestChannel& left = run.channels[k].channel;
    ASSERT_EQ(left.side, host::ManifestSide::kLeft);
    ASSERT_EQ(run.channels[k + 1].channel.axle, left.axle);
    const std::optional<host::AxleClearance> axle =
        host::axle_clearance(settled(run.channels[k]), settled(run.channels[k + 1]));
    ASSERT_TRUE(axle.has_value()) << "axle " << left.axle;
    for (const auto& [side, expected] :
         {std::pair{"left", axle->left_mm}, {"right", axle->right_mm}}) {
      const auto history = opened->wear_history({"A-1", left.axle, side});
      ASSERT_EQ(history.size(), 1u);
      ASSERT_TRUE(history[0].clearance_mm.has_value());
      EXPECT_DOUBLE_EQ(*history[0].clearance_mm, expected) << "axle " << left.axle << " " << side;
      // No maintenance recorded: the wear is against the sensor's 2 mm setting on a new flange.
      ASSERT_TRUE(history[0].wear_mm.has_value());
      EXPECT_DOUBLE_EQ(*history[0].wear_mm, expected - 2.0) << "axle " << left.axle << " " << side;
    }
  }
}

TEST_F(StoreCommands, WearFollowsEveryWheelOfRunsStoredByFlangeRun) {
  const std::string store = "sqlite:" + path("wear.db");
  for (const auto& [at, odometer] : {std::pair{"2026-03-01T06:00:00Z", "1000"},
                                     {"2026-03-02T06:00:00Z", "1300"},
                                     {"2026-03-03T06:00:00Z", "1600"}}) {
    flange_ok({"run", "--manifest", path("loco/locomotive.json"), "--calibration",
               path("model_csv.json"), "--coeffs", kMeasurement, "--store", store, "--locomotive",
               "W-1", "--started-at", at, "--distance-km", "300", "--odometer-km", odometer});
  }
  const std::string out = flange_ok({"wear", "--store", store, "--out", path("wear")});
  EXPECT_NE(out.find("wear: 12 wheels from " + store), std::string::npos) << out;
  const nlohmann::json wear = nlohmann::json::parse(std::ifstream(path("wear/wear.json")));
  ASSERT_EQ(wear["wheels"].size(), 12u);
  for (const nlohmann::json& wheel : wear["wheels"]) {
    ASSERT_EQ(wheel["runs"].size(), 3u) << wheel.dump();
    EXPECT_DOUBLE_EQ(wheel["runs"][2]["odometer_km"].get<double>(), 1600.0);
  }
}

TEST_F(StoreCommands, TwoFlangeRunsAtOnceLoseNothing) {
  const std::string store = "sqlite:" + path("two.db");
  host::open_store(store);
  std::string both;
  for (const char* loco : {"L1", "L2"}) {
    both += std::string(FLANGE_BINARY_DIR) + "/flange run --manifest " +
            path("loco/locomotive.json") + " --calibration " + path("model_csv.json") +
            " --coeffs " + kMeasurement + " --store " + store + " --locomotive " + loco +
            " >/dev/null & pid_" + loco + "=$!; ";
  }
  both += "wait $pid_L1 && wait $pid_L2";
  ASSERT_EQ(std::system(("bash -c '" + both + "'").c_str()), 0) << both;
  auto opened = host::open_store(store);
  EXPECT_EQ(opened->run_count(), 2u);
  EXPECT_EQ(opened->wear_history({"L1", 1, "left"}).size(), 1u);
  EXPECT_EQ(opened->wear_history({"L2", 1, "left"}).size(), 1u);
}

TEST_F(StoreCommands, BadOrUnreachableStoresStopTheRunBeforeItWrites) {
  const std::vector<std::pair<std::string, int>> cases = {
      {"mysql://depot/fleet", 2},
      {"sqlite:", 2},
      {"sqlite:" + path("no_such_folder/fleet.db"), 1},
      {"postgresql://flange@/fleet?host=" + path("no_server"), 1}};
  for (const auto& [url, status] : cases) {
    const FlangeOutcome outcome = run_flange_captured(
        {"run", "--input", path("loco/channel_00.csv"), "--calibration", path("model_csv.json"),
         "--coeffs", kMeasurement, "--store", url, "--out", path("never.csv")});
    EXPECT_EQ(outcome.status, status) << url << ": " << outcome.err;
    EXPECT_EQ(outcome.err.find("flange run: store "), 0u) << outcome.err;
    EXPECT_EQ(std::count(outcome.err.begin(), outcome.err.end(), '\n'), 1) << outcome.err;
    EXPECT_FALSE(fs::exists(path("never.csv"))) << url;
  }
  const FlangeOutcome calibrate =
      run_flange_captured({"calibrate", "--store", "oracle://x", "--out", path("never.json")});
  EXPECT_EQ(calibrate.status, 2) << calibrate.err;
}

}  // namespace
}  // namespace flange::cli
