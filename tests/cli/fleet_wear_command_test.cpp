// SPDX-License-Identifier: MIT
// A small fleet as a user follows it: `flange simulate --scenario fleet` into an SQLite store,
// then `flange wear --truth` against the truth file the simulation wrote beside it. Every wheel's
// rate within 10 % of the truth (or the truth inside its interval), every reprofiling the runs
// can show found, every drifting sensor flagged and no healthy one. And the bad arguments.
#include <gtest/gtest.h>

#include <fmt/format.h>
#include <fstream>
#include <nlohmann/json.hpp>

#include "flange_in_process.h"
#include "test_files.h"

namespace flange::cli {
namespace {

namespace fs = std::filesystem;
using testing::FlangeOutcome;
using testing::fresh_test_dir;
using testing::command_text;
using testing::run_flange_captured;

// Two locomotives over 45 days, seed 11: 24 wheels, reprofilings and a drifting sensor.
TEST(FleetWearCommand, ASmallFleetMatchesItsTruth) {
  const fs::path dir = fresh_test_dir("fleet_wear_small");
  const std::string store = "sqlite:" + (dir / "fleet.db").string();
  const std::vector<std::string> simulate{"simulate", "--scenario", "fleet", "--locomotives",
                                          "2",        "--days",     "45",    "--seed",
                                          "11",       "--store",    store};
  const FlangeOutcome simulated = run_flange_captured(simulate);
  ASSERT_EQ(simulated.status, 0) << command_text(simulate) << "\n" << simulated.err;
  ASSERT_TRUE(fs::exists(dir / "fleet_truth.json"));
  const std::vector<std::string> wear{"wear",
                                      "--store",
                                      store,
                                      "--out",
                                      (dir / "wear").string(),
                                      "--truth",
                                      (dir / "fleet_truth.json").string()};
  const FlangeOutcome estimated = run_flange_captured(wear);
  EXPECT_EQ(estimated.status, 0) << command_text(wear) << "\n" << estimated.out << estimated.err;
  for (const char* name :
       {"wear.json", "wear.csv", "index.html", "wear_01.svg", "wear_02.svg", "truth_check.json"}) {
    EXPECT_TRUE(fs::exists(dir / "wear" / name)) << name;
  }
  std::ifstream file(dir / "wear" / "truth_check.json");
  const nlohmann::json check = nlohmann::json::parse(file);
  EXPECT_EQ(check.at("wheels_checked").get<int>(), 24);
  EXPECT_EQ(check.at("rates_ok").get<int>(), 24) << estimated.out;
  EXPECT_GT(check.at("reprofilings").get<int>(), 0) << "the seed should reprofile a wheel";
  EXPECT_EQ(check.at("reprofilings_found"), check.at("reprofilings")) << estimated.out;
  EXPECT_GT(check.at("drifting").get<int>(), 0);
  EXPECT_EQ(check.at("drifting_flagged"), check.at("drifting")) << estimated.out;
  EXPECT_EQ(check.at("healthy_flagged").get<int>(), 0) << estimated.out;
  // The fleet's bend and trend the dates were made with, as printed, and the b they used.
  const nlohmann::json bend =
      nlohmann::json::parse(std::ifstream(dir / "wear" / "wear.json")).at("fleet_acceleration");
  ASSERT_TRUE(bend.is_object()) << estimated.out;
  const double b = bend.at("per_mm").get<double>(), se = bend.at("per_mm_se").get<double>();
  EXPECT_NE(estimated.out.find(fmt::format("b = {:.4f} per mm (se {:.4f})", b, se)),
            std::string::npos)
      << estimated.out;
  EXPECT_NEAR(bend.at("per_mm_in_dates").get<double>(), b * b * b / (b * b + se * se), 1e-12);
  EXPECT_GT(bend.at("trend_per_day_se").get<double>(), 0.0);
  EXPECT_GT(bend.at("dof").get<int>(), 0);
}

TEST(FleetWearCommand, BadArgumentsNameTheOptionAndItsRange) {
  const fs::path dir = fresh_test_dir("fleet_wear_bad");
  const std::string store = "sqlite:" + (dir / "fleet.db").string();
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
      {{"simulate", "--scenario", "fleet", "--locomotives", "0", "--days", "3", "--store", store},
       "--locomotives: 0 is outside its valid range: a whole number 1 to 100"},
      {{"simulate", "--scenario", "fleet", "--locomotives", "2", "--days", "-4", "--store", store},
       "--days"},
      {{"simulate", "--scenario", "fleet", "--days", "3", "--store", store},
       "--locomotives is required with --scenario fleet: a whole number 1 to 100"},
      {{"simulate", "--scenario", "fleet", "--locomotives", "1", "--days", "3", "--wheels", "4",
        "--store", store},
       "--wheels: the fleet scenario records every wheel"},
      {{"simulate", "--scenario", "loco", "--locomotives", "2", "--seed", "1", "--out",
        (dir / "x.csv").string()},
       "--locomotives: only the fleet scenario takes it"},
      {{"simulate", "--scenario", "fleet", "--locomotives", "1", "--days", "3", "--store",
        "mysql://x"},
       "--store"},
      {{"wear", "--store", store, "--out", (dir / "w").string(), "--warning-mm", "-3"}, "warning"}};
  for (const auto& [args, message] : cases) {
    const FlangeOutcome outcome = run_flange_captured(args);
    EXPECT_EQ(outcome.status, 2) << command_text(args) << "\n" << outcome.err;
    EXPECT_NE(outcome.err.find(message), std::string::npos) << command_text(args) << "\n"
                                                            << outcome.err;
    EXPECT_EQ(std::count(outcome.err.begin(), outcome.err.end(), '\n'), 1) << outcome.err;
  }
}

}  // namespace
}  // namespace flange::cli
