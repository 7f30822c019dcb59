// SPDX-License-Identifier: MIT
// `flange wear --plan` as a depot runs it on a small simulated fleet: plan.csv and the page's
// section, soonest first and all before the horizon, the CSV alone on stdout with --plan-csv -.
// And its bad inputs, each refused with one line and its documented exit status before anything
// is written: a date before the last run, a risk outside (0, 1), a store with no runs (or none
// at all), a truth file of another fleet.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "flange_in_process.h"
#include "store.h"
#include "test_files.h"

namespace flange::cli {
namespace {

namespace fs = std::filesystem;
using testing::FlangeOutcome;
using testing::fresh_test_dir;
using testing::command_text;
using testing::run_flange_captured;

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream stream(text);
  for (std::string line; std::getline(stream, line);) lines.push_back(line);
  return lines;
}

// One locomotive over 40 days from 2026-01-01 (seed 11), simulated once for every test here, in a
// folder of this process's own: CTest runs the tests of this file as processes side by side.
class WearPlanCommand : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = fresh_test_dir("wear_plan_command_" + std::to_string(::getpid()));
    store_ = "sqlite:" + (dir_ / "fleet.db").string();
    const std::vector<std::string> simulate{"simulate", "--scenario", "fleet", "--locomotives",
                                            "1",        "--days",     "40",    "--seed",
                                            "11",       "--store",    store_};
    const FlangeOutcome simulated = run_flange_captured(simulate);
    ASSERT_EQ(simulated.status, 0) << command_text(simulate) << "\n" << simulated.err;
  }
  std::vector<std::string> wear(const std::string& out, std::vector<std::string> more) const {
    std::vector<std::string> args{"wear", "--store", store_, "--out", (dir_ / out).string()};
    args.insert(args.end(), more.begin(), more.end());
    return args;
  }
  // The case is refused with `status` and one line holding `message`; `out` is not made.
  void expect_refused(const std::vector<std::string>& args, int status, const std::string& message,
                      const std::string& out) const {
    const FlangeOutcome outcome = run_flange_captured(args);
    EXPECT_EQ(outcome.status, status) << command_text(args) << "\n" << outcome.err;
    EXPECT_NE(outcome.err.find(message), std::string::npos) << command_text(args) << "\n"
                                                            << outcome.err;
    EXPECT_EQ(lines_of(outcome.err).size(), 1u) << command_text(args) << "\n" << outcome.err;
    EXPECT_FALSE(fs::exists(dir_ / out)) << command_text(args) << " wrote " << out;
  }
  static fs::path dir_;
  static std::string store_;
};

fs::path WearPlanCommand::dir_;
std::string WearPlanCommand::store_;

TEST_F(WearPlanCommand, ThePlanListsTheWheelsDueBeforeTheDateSoonestFirst) {
  const std::vector<std::string> args = wear("plan", {"--plan", "--before", "2027-01-01"});
  const FlangeOutcome outcome = run_flange_captured(args);
  ASSERT_EQ(outcome.status, 0) << command_text(args) << "\n" << outcome.err;
  std::ifstream csv_file(dir_ / "plan" / "plan.csv");
  std::stringstream csv;
  csv << csv_file.rdbuf();
  const std::vector<std::string> rows = lines_of(csv.str());
  ASSERT_GE(rows.size(), 2u) << "seed 11 should have a wheel due within a year\n" << outcome.out;
  EXPECT_EQ(rows[0].substr(0, 29), "locomotive,axle,side,due_date");
  std::string previous;
  for (std::size_t k = 1; k < rows.size(); ++k) {
    std::vector<std::string> fields;
    std::istringstream row(rows[k]);
    for (std::string field; std::getline(row, field, ',');) fields.push_back(field);
    ASSERT_EQ(fields.size(), 9u) << rows[k];
    const std::string& due = fields[3];
    EXPECT_LT(due, "2027-01-01") << rows[k];
    EXPECT_GE(due, previous) << rows[k];
    EXPECT_GE(due, "2026-02-01") << "not before the last runs: " << rows[k];
    previous = due;
  }
  std::ifstream page(dir_ / "plan" / "index.html");
  std::stringstream html;
  html << page.rdbuf();
  EXPECT_NE(html.str().find("Reprofiling plan before 2027-01-01"), std::string::npos);
  EXPECT_NE(outcome.out.find(
                fmt::format("plan: {} wheels to reprofile before 2027-01-01", rows.size() - 1)),
            std::string::npos)
      << outcome.out;
  // A lower risk brings every date forward, so no fewer wheels are due; stdout holds the CSV.
  const FlangeOutcome cautious = run_flange_captured(wear(
      "plan_cautious", {"--plan", "--before", "2027-01-01", "--risk", "0.001", "--plan-csv", "-"}));
  ASSERT_EQ(cautious.status, 0) << cautious.err;
  EXPECT_EQ(cautious.out.substr(0, 29), "locomotive,axle,side,due_date");
  EXPECT_GE(lines_of(cautious.out).size(), rows.size());
  EXPECT_NE(cautious.err.find("wear: 12 wheels"), std::string::npos) << cautious.err;
}

TEST_F(WearPlanCommand, APlanDateBeforeTheLastRunIsRefused) {
  expect_refused(wear("early", {"--plan", "--before", "2026-01-15"}), 2,
                 "--before: 2026-01-15 is not after the store's last run", "early");
  expect_refused(wear("not_date", {"--plan", "--before", "soon"}), 2,
                 "--before: 'soon' is not a date", "not_date");
  expect_refused(wear("no_date", {"--plan"}), 2, "--before is required with --plan", "no_date");
}

TEST_F(WearPlanCommand, ARiskOutsideZeroToOneIsRefused) {
  for (const char* risk : {"0", "1", "1.5", "-0.1"}) {
    expect_refused(wear("risk", {"--plan", "--before", "2027-01-01", "--risk", risk}), 2,
                   "--risk: ", "risk");
    expect_refused(wear("risk", {"--plan", "--before", "2027-01-01", "--risk", risk}), 2,
                   "is outside its valid range: a probability strictly between 0 and 1", "risk");
  }
}

TEST_F(WearPlanCommand, AStoreWithNoRunsOrNoStoreIsRefused) {
  const std::string empty = "sqlite:" + (dir_ / "empty.db").string();
  host::open_store(empty);  // the schema, no run
  std::vector<std::string> args{
      "wear",   "--store",  empty,       "--out", (dir_ / "empty").string(),
      "--plan", "--before", "2027-01-01"};
  expect_refused(args, 1, "no run with a wheel's wear estimate", "empty");
  const fs::path missing = dir_ / "missing.db";
  args[2] = "sqlite:" + missing.string();
  expect_refused(args, 1, "no such file", "empty");
  EXPECT_FALSE(fs::exists(missing)) << "flange wear made a store";
}

TEST_F(WearPlanCommand, ATruthFileOfAnotherFleetIsRefused) {
  nlohmann::json truth;
  std::ifstream(dir_ / "fleet_truth.json") >> truth;
  const auto refused_with = [&](const nlohmann::json& other, const std::string& name,
                                const std::string& message) {
    const fs::path file = dir_ / (name + ".json");
    std::ofstream(file) << other.dump();
    expect_refused(wear(name, {"--truth", file.string()}), 2, message, name);
  };
  nlohmann::json renamed = truth;
  renamed["locomotives"][0]["name"] = "L77";
  refused_with(renamed, "renamed", "the store's locomotive L01 is not in it");
  nlohmann::json later = truth;
  later["first_day"] = "2026-01-06";  // five days after the simulation's
  refused_with(later, "later", "is outside its days");
  nlohmann::json other_distances = truth;
  for (auto& km : other_distances["locomotives"][0]["day_km"]) km = km.get<double>() * 1.1 + 3.0;
  refused_with(other_distances, "other_distances", "odometer steps between runs are not");
  // The fleet's own truth passes this check (the comparison itself then runs).
  const FlangeOutcome own =
      run_flange_captured(wear("own", {"--truth", (dir_ / "fleet_truth.json").string()}));
  EXPECT_EQ(own.err.find("another fleet"), std::string::npos) << own.err;
  EXPECT_TRUE(fs::exists(dir_ / "own" / "truth_check.json"));
}

}  // namespace
}  // namespace flange::cli
