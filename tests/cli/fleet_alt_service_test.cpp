// SPDX-License-Identifier: MIT
// The service path end to end on the second fleet reality, on SQLite and PostgreSQL: a small
// depot written by `flange simulate --scenario fleet-alt`, its bench sessions into `flange
// calibrate --store`, its maintenance records into `flange maintenance`, every locomotive-day
// into `flange run --manifest --store` with its date, distance and odometer (as
// scripts/fleet_service.sh does), then `flange wear --truth`. Checked: every run stored with
// each wheel's wear (the fleet table shows it for every wheel), the odometer counted on over
// the reset, the references after a lathe pass and a sensor replacement, and `flange wear`
// against the truth: every wheel's rate within 10 % or inside its interval, every reprofiling
// found in the data, the drifting sensor flagged (six weeks after its drift began; at four, on
// the same fleet cut at 42 days, it is not yet: docs/fleet.md) and no healthy sensor flagged.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "flange_in_process.h"
#include "store.h"
#include "store_test_backends.h"
#include "store_test_fixture.h"
#include "test_files.h"

namespace flange::cli {
namespace {

namespace fs = std::filesystem;
using testing::command_text;
using testing::FlangeOutcome;
using testing::run_flange_captured;
using testing::StoreBackendUnderTest;

const std::string kMeasurement =
    std::string(FLANGE_SOURCE_DIR) + "/coeffs/measurement_sos/filter.json";

void flange_ok(const std::vector<std::string>& args) {
  const FlangeOutcome outcome = run_flange_captured(args);
  ASSERT_EQ(outcome.status, 0) << command_text(args) << "\n" << outcome.err;
}

std::vector<std::vector<std::string>> csv_rows(const fs::path& path) {
  std::ifstream file(path);
  std::string line;
  std::getline(file, line);  // header
  std::vector<std::vector<std::string>> rows;
  while (std::getline(file, line)) {
    std::vector<std::string> fields;
    std::stringstream stream(line);
    std::string field;
    while (std::getline(stream, field, ',')) fields.push_back(field);
    if (!line.empty() && line.back() == ',') fields.emplace_back();
    rows.push_back(fields);
  }
  return rows;
}

// maintenance.csv's records through `flange maintenance`, as scripts/fleet_service.sh does.
void record_maintenance(const fs::path& depot, const std::string& store) {
  for (const auto& row : csv_rows(depot / "maintenance.csv")) {
    ASSERT_EQ(row.size(), 8u);
    std::vector<std::string> args{"maintenance", "--store",       store,  "--locomotive",
                                  row[1],        "--kind",        row[4], "--at",
                                  row[0],        "--odometer-km", row[5]};
    for (const auto& [value, option] : {std::pair{row[2], "--axle"},
                                        {row[3], "--side"},
                                        {row[6], "--from-axle"},
                                        {row[7], "--sensor"}}) {
      if (value.empty()) continue;
      args.push_back(option);
      args.push_back(value);
    }
    flange_ok(args);
  }
}

void run_days(const fs::path& depot, const std::string& store) {
  for (const auto& row : csv_rows(depot / "runs.csv")) {
    ASSERT_EQ(row.size(), 5u);
    flange_ok({"run", "--manifest", (depot / row[2]).string(), "--calibration",
               (depot / "model.json").string(), "--coeffs", kMeasurement, "--store", store,
               "--locomotive", row[1], "--started-at", row[0], "--distance-km", row[3],
               "--odometer-km", row[4]});
  }
}

// The truth file's own limit dates (sim/fleet_alt/fleet_alt_limits.h) are the ones checked: each
// wheel with a fitted rate has its dates' coverage, and its true dates are the file's.
void expect_the_truths_own_dates_checked(const nlohmann::json& check, const fs::path& truth_file,
                                         int wheels) {
  const nlohmann::json truth = nlohmann::json::parse(std::ifstream(truth_file));
  int dated = 0;
  for (const nlohmann::json& w : check["wheels"]) {
    for (const nlohmann::json& loco : truth["locomotives"]) {
      if (loco["name"] != w["locomotive"]) continue;
      const nlohmann::json& wheel =
          loco["wheels"][2 * (w["axle"].get<int>() - 1) + (w["side"] == "left" ? 0 : 1)];
      EXPECT_EQ(w["true_warning_date"], wheel["true_warning_date"]);
      EXPECT_EQ(w["true_critical_date"], wheel["true_critical_date"]);
    }
    if (!w["warning_coverage"].is_null() && !w["critical_coverage"].is_null()) ++dated;
  }
  EXPECT_EQ(dated, wheels);
}

class FleetAltService : public ::testing::TestWithParam<StoreBackendUnderTest> {};

TEST_P(FleetAltService, WearThroughTheServicePathAgainstTheTruth) {
  const std::string name = "fleet_alt_service_" + testing::backend_test_name(GetParam());
  const fs::path dir = testing::fresh_test_dir(name);
  const fs::path depot = dir / "depot";
  const std::string store = testing::fresh_store_url(GetParam(), name);
  flange_ok({"simulate", "--scenario", "fleet-alt", "--locomotives", "2", "--days", "56", "--seed",
             "21", "--duration", "120", "--out", depot.string()});
  for (int n = 1; n <= 3; ++n) {
    flange_ok({"calibrate", "--store", store, "--append",
               (depot / "bench" / ("bench_" + std::to_string(n) + ".csv")).string(), "--out",
               (depot / "model.json").string()});
  }
  record_maintenance(depot, store);
  run_days(depot, store);
  const std::vector<std::string> wear{"wear",
                                      "--store",
                                      store,
                                      "--out",
                                      (dir / "wear").string(),
                                      "--truth",
                                      (depot / "fleet_truth.json").string()};
  const FlangeOutcome outcome = run_flange_captured(wear);
  ASSERT_TRUE(outcome.status == 0 || outcome.status == 1) << command_text(wear) << outcome.err;
  const nlohmann::json check = nlohmann::json::parse(std::ifstream(dir / "wear/truth_check.json"));
  SCOPED_TRACE(command_text(wear) + "\n" + outcome.out);

  // Every wheel's wear in the store's fleet table, from runs made as the board's are.
  const std::unique_ptr<host::Store> opened = host::open_store(store);
  const std::vector<host::FleetRow> table = opened->fleet_table();
  ASSERT_EQ(table.size(), 24u);
  for (const host::FleetRow& row : table) {
    EXPECT_TRUE(row.last_wear_mm.has_value()) << row.wheel.locomotive << " " << row.wheel.axle;
    EXPECT_TRUE(row.wear_rate_mm_per_1000km.has_value());
  }
  // The reset odometer counted on: each wheel's runs in time order never run backwards.
  for (const host::StoredWheel& wheel : opened->wheels()) {
    double last = 0.0;
    for (const host::WearPoint& point : opened->wear_history(wheel.wheel.wheel)) {
      EXPECT_GE(point.odometer_km, last) << point.started_at;
      last = point.odometer_km;
    }
  }
  // The depot's records as the reference: a reprofiled wheel's wear is 0 at its first run after
  // the lathe; a replaced sensor's wheel keeps the wear it had.
  for (const auto& row : csv_rows(depot / "maintenance.csv")) {
    if (row[4] != "reprofile" && row[4] != "sensor_replaced") continue;
    const host::WheelKey key{row[1], std::stoi(row[2]), row[3].empty() ? "left" : row[3]};
    std::optional<double> before, after;
    for (const host::WearPoint& point : opened->wear_history(key)) {
      if (point.started_at < row[0]) before = point.wear_mm;
      if (point.started_at > row[0] && !after) after = point.wear_mm;
    }
    if (!after || !before) continue;
    const double expected = row[4] == "reprofile" ? 0.0 : *before;
    EXPECT_NEAR(*after, expected, 1e-9) << row[4] << " " << row[0];
  }
  EXPECT_GT(check["reprofilings"].get<int>(), 0) << "the seed must show a lathe pass";
  EXPECT_EQ(check["reprofilings_found"], check["reprofilings"]);
  EXPECT_EQ(check["wheels_checked"], 24);
  EXPECT_EQ(check["rates_ok"], 24);
  EXPECT_EQ(check["drifting"], 1) << "the seed must show a drifting sensor";
  EXPECT_EQ(check["drifting_flagged"], 1);
  EXPECT_EQ(check["healthy_flagged"], 0);
  EXPECT_TRUE(check["passed"].get<bool>());
  EXPECT_EQ(outcome.status, 0);
  expect_the_truths_own_dates_checked(check, depot / "fleet_truth.json", 24);
}

// A small depot's folder and a store with its calibration: for the refusals below.
fs::path small_depot(const std::string& name, std::string& store) {
  const fs::path dir = testing::fresh_test_dir(name);
  store = "sqlite:" + (dir / "store.db").string();
  flange_ok({"simulate", "--scenario", "fleet-alt", "--locomotives", "1", "--days", "21", "--seed",
             "3", "--duration", "60", "--out", (dir / "depot").string()});
  flange_ok({"calibrate", "--store", store, "--append", (dir / "depot/bench/bench_1.csv").string(),
             "--out", (dir / "depot/model.json").string()});
  return dir / "depot";
}

TEST(FleetAltServiceRefusals, AMaintenanceRecordMissingWhatItsKindNeeds) {
  std::string store;
  small_depot("fleet_alt_refusals", store);
  const std::vector<std::string> base{
      "maintenance", "--store", store, "--locomotive", "A01", "--at", "2027-03-05T12:00:00Z"};
  for (const auto& [extra, named] : std::vector<std::pair<std::vector<std::string>, std::string>>{
           {{"--kind", "reprofile"}, "--axle"},
           {{"--kind", "wheelset_moved", "--axle", "2"}, "--from-axle"},
           {{"--kind", "wheelset_moved", "--axle", "2", "--from-axle", "2"}, "--from-axle"},
           {{"--kind", "sensor_replaced", "--axle", "2"}, "--side"},
           {{"--kind", "odometer_reset", "--axle", "2", "--odometer-km", "5"}, "--axle"},
           {{"--kind", "odometer_reset"}, "--odometer-km"},
           {{"--kind", "reprofile", "--axle", "7"}, "--axle"},
           {{"--kind", "repainted", "--axle", "1"}, "--kind"}}) {
    std::vector<std::string> args = base;
    args.insert(args.end(), extra.begin(), extra.end());
    const FlangeOutcome outcome = run_flange_captured(args);
    EXPECT_EQ(outcome.status, 2) << command_text(args);
    EXPECT_NE(outcome.err.find(named), std::string::npos) << command_text(args) << outcome.err;
    EXPECT_EQ(std::count(outcome.err.begin(), outcome.err.end(), '\n'), 1) << outcome.err;
  }
  EXPECT_TRUE(host::open_store(store)->maintenance_events("").empty());
}

TEST(FleetAltServiceRefusals, AnOdometerThatRunsBackwardsWithoutARecordedReset) {
  std::string store;
  const fs::path depot = small_depot("fleet_alt_odometer", store);
  const auto runs = csv_rows(depot / "runs.csv");
  ASSERT_GE(runs.size(), 2u);
  auto run_args = [&](const std::vector<std::string>& row, const std::string& odometer) {
    return std::vector<std::string>{"run",
                                    (std::string("--manifest")),
                                    (depot / row[2]).string(),
                                    "--calibration",
                                    (depot / "model.json").string(),
                                    "--coeffs",
                                    kMeasurement,
                                    "--store",
                                    store,
                                    "--locomotive",
                                    row[1],
                                    "--started-at",
                                    row[0],
                                    "--distance-km",
                                    row[3],
                                    "--odometer-km",
                                    odometer};
  };
  flange_ok(run_args(runs[0], runs[0][4]));
  const std::vector<std::string> backwards = run_args(runs[1], "12.5");
  const FlangeOutcome refused = run_flange_captured(backwards);
  EXPECT_EQ(refused.status, 2) << command_text(backwards);
  EXPECT_NE(refused.err.find("--odometer-km 12.5"), std::string::npos) << refused.err;
  EXPECT_EQ(host::open_store(store)->run_count(), 1u);
  // Recorded, the reset is counted on from: the run is stored after the first one's odometer.
  flange_ok({"maintenance", "--store", store, "--locomotive", runs[1][1], "--kind",
             "odometer_reset", "--at", runs[0][0].substr(0, 11) + "23:00:00Z", "--odometer-km",
             runs[0][4]});
  flange_ok(backwards);
  const std::vector<host::WearPoint> history =
      host::open_store(store)->wear_history({runs[1][1], 1, "left"});
  ASSERT_EQ(history.size(), 2u);
  EXPECT_NEAR(history[1].odometer_km, std::stod(runs[0][4]) + 12.5, 1e-6);
}

INSTANTIATE_TEST_SUITE_P(Backends, FleetAltService,
                         ::testing::Values(StoreBackendUnderTest::kSqlite,
                                           StoreBackendUnderTest::kPostgresql),
                         testing::backend_param_name);

}  // namespace
}  // namespace flange::cli
