// SPDX-License-Identifier: MIT
// The store's calls on both backends: what is written is read back, in the order promised.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>

#include "store_migration.h"
#include "store_test_fixture.h"
#include "store_test_records.h"

namespace flange::testing {
namespace {

using host::WheelKey;

TEST_P(StoreTest, NewStoreHasTheCurrentSchemaAndReopens) {
  {
    auto store = open();
    EXPECT_EQ(store->schema_version(), host::kStoreSchemaVersion);
    EXPECT_EQ(store->run_count(), 0u);
    EXPECT_EQ(store->backend(),
              GetParam() == StoreBackendUnderTest::kSqlite ? "sqlite" : "postgresql");
  }
  auto again = open();  // nothing to migrate
  EXPECT_EQ(again->schema_version(), host::kStoreSchemaVersion);
}

TEST_P(StoreTest, RecordsARunWithItsWheelsEventsAndTrace) {
  auto store = open();
  store->upsert_locomotive({"G2000-01", "Vossloh G2000"});
  store->upsert_sensor({"S-100", "inductive", WheelKey{"G2000-01", 1, "left"}, test_time(0)});
  const auto run_id = store->record_run(test_run("G2000-01", test_time(1), 1200.0, 0.5));

  EXPECT_EQ(store->run_count(), 1u);
  const auto wheels = store->wheels();
  ASSERT_EQ(wheels.size(), 12u);
  EXPECT_EQ(wheels[0].wheel.wheel, (WheelKey{"G2000-01", 1, "left"}));
  EXPECT_EQ(wheels[0].sensor_serial, "S-100");
  EXPECT_EQ(wheels[11].wheel.wheel, (WheelKey{"G2000-01", 6, "right"}));
  EXPECT_EQ(wheels[11].wheel.channel, 11);
  EXPECT_EQ(wheels[11].sensor_serial, "");

  const auto history = store->wear_history({"G2000-01", 6, "right"});
  ASSERT_EQ(history.size(), 1u);
  EXPECT_EQ(history[0].run_id, run_id);
  EXPECT_EQ(history[0].started_at, test_time(1));
  EXPECT_DOUBLE_EQ(history[0].odometer_km, 1200.0);
  EXPECT_DOUBLE_EQ(history[0].wear_mm.value(), 0.61);
  EXPECT_DOUBLE_EQ(history[0].temp_c, 31.0);
  EXPECT_EQ(store->wear_history({"G2000-01", 1, "left"})[0].sensor_serial, "S-100");

  const auto events = store->alarm_events("G2000-01");
  ASSERT_EQ(events.size(), 2u);
  EXPECT_EQ(events[0].wheel, (WheelKey{"G2000-01", 1, "left"}));
  EXPECT_EQ(events[0].what, "warning");
  EXPECT_FALSE(events[1].wheel.has_value());
  EXPECT_EQ(events[1].what, "wear_step 0.73 mm");
  EXPECT_EQ(store->run_trace(run_id).size(), 36u);
  EXPECT_EQ(store->locomotives()[0].description, "Vossloh G2000");
}

TEST_P(StoreTest, WearHistoryIsInTimeOrderAndTheFleetRateFollowsTheLatestReprofiling) {
  auto store = open();
  // Recorded out of order; 0.2 mm per 1000 km before the reprofiling on day 5, 0.3 after.
  for (const int day : {3, 0, 4, 1, 2}) {
    store->record_run(test_run("L1", test_time(day), 1000.0 * day, 0.2 * day));
  }
  store->record_maintenance(
      {{"L1", 2, "left"}, test_time(5), 5000.0, "reprofile", "lathe 2", std::nullopt});
  for (int day = 5; day < 9; ++day) {
    store->record_run(test_run("L1", test_time(day, 1), 1000.0 * day, 0.3 * (day - 5)));
  }
  const auto history = store->wear_history({"L1", 1, "left"});
  ASSERT_EQ(history.size(), 9u);
  for (std::size_t i = 1; i < history.size(); ++i) {
    EXPECT_LT(history[i - 1].started_at, history[i].started_at);
  }
  const auto fleet = store->fleet_table();
  ASSERT_EQ(fleet.size(), 12u);
  const auto& reprofiled = fleet[2];  // axle 2 left
  EXPECT_EQ(reprofiled.wheel, (WheelKey{"L1", 2, "left"}));
  EXPECT_EQ(reprofiled.runs, 9u);
  EXPECT_EQ(reprofiled.runs_since_maintenance, 4u);
  EXPECT_NEAR(reprofiled.wear_rate_mm_per_1000km.value(), 0.3, 1e-9);
  EXPECT_EQ(reprofiled.last_maintenance_at, test_time(5));
  EXPECT_NEAR(reprofiled.last_wear_mm.value(), 0.9 + 0.02, 1e-12);
  EXPECT_EQ(fleet[0].runs_since_maintenance, 9u);  // axle 1 left: never reprofiled
  EXPECT_EQ(fleet[0].alarm_events, 9u);
  const auto maintenance = store->maintenance_events("L1");
  ASSERT_EQ(maintenance.size(), 1u);
  EXPECT_EQ(maintenance[0].event.note, "lathe 2");
  EXPECT_TRUE(store->maintenance_events("other").empty());
}

// A wheelset move keeps the axle it came from as data beside the depot's note; the column takes
// the project's axles only.
TEST_P(StoreTest, AWheelsetMoveKeepsTheAxleItCameFromBesideItsNote) {
  auto store = open();
  store->record_maintenance(
      {{"L1", 1, "right"}, test_time(2), 2000.0, "wheelset_moved", "from the spare; 3 left", 6});
  store->record_maintenance(
      {{"L1", 1, "right"}, test_time(3), 3000.0, "reprofile", "lathe", std::nullopt});
  EXPECT_THROW(store->record_maintenance(
                   {{"L1", 2, "right"}, test_time(4), 4000.0, "wheelset_moved", "", 7}),
               host::StoreError);
  const auto events = store->maintenance_events("L1");
  ASSERT_EQ(events.size(), 2u);
  EXPECT_EQ(events[0].event.from_axle, 6);
  EXPECT_EQ(events[0].event.note, "from the spare; 3 left");
  EXPECT_EQ(events[1].event.from_axle, std::nullopt);
  EXPECT_EQ(events[1].event.note, "lathe");
}

TEST_P(StoreTest, TheFleetTableTheWritesKeepEqualsOneRecomputedFromTheRuns) {
  auto store = open();
  write_mixed_history(*store);
  expect_fleet_table_matches_runs(*store);
  const auto fleet = store->fleet_table();
  EXPECT_EQ(fleet.front().wheel, (WheelKey{"M", 1, "left"}));
  EXPECT_EQ(fleet.front().last_maintenance_at, test_time(6, 1));  // not the backdated one
  EXPECT_EQ(fleet.front().runs_since_maintenance, 3u);
}

TEST_P(StoreTest, NamesWithQuotesAndSemicolonsAreStoredAsData) {
  auto store = open();
  const std::string hostile = "O'Brien\"; DROP TABLE runs; --";
  store->upsert_locomotive({hostile, "it's; ok"});
  store->record_run(test_run(hostile, test_time(0), 10.0, 0.1));
  store->record_maintenance(
      {{hostile, 1, "right"}, test_time(1), 20.0, "reprofile", "'; --", std::nullopt});
  EXPECT_EQ(store->run_count(), 1u);
  EXPECT_EQ(store->locomotives().at(0).name, hostile);
  EXPECT_EQ(store->wear_history({hostile, 1, "right"}).size(), 1u);
  EXPECT_EQ(store->maintenance_events(hostile).at(0).event.note, "'; --");
  EXPECT_EQ(store->alarm_events(hostile).size(), 2u);
}

TEST_P(StoreTest, KeepsBenchSessionsRowsAndEveryCalibration) {
  auto store = open();
  host::SessionRecord session{host::SessionKind::kBench, "bench-1", test_time(0), 10.0, "db.csv",
                              std::string(64, 'b'),      "S-7"};
  const std::vector<host::BenchRow> rows = {{0.0, 1.5, 20.0, 2.25}, {0.1, std::nullopt, 21.0, 2.5}};
  const auto id = store->record_session(session, rows);
  EXPECT_EQ(store->record_session(session, rows), id);  // the same session is not repeated
  const auto back = store->bench_rows(id);
  ASSERT_EQ(back.size(), 2u);
  EXPECT_DOUBLE_EQ(back[0].clearance_mm.value(), 1.5);
  EXPECT_FALSE(back[1].clearance_mm.has_value());
  EXPECT_DOUBLE_EQ(back[1].voltage_v, 2.5);
  store->record_calibration({test_time(1), "S-7", "{}", 2, 0.01, {id}});
  store->record_calibration({test_time(2), "S-7", "{\"refit\": true}", 2, 0.02, {id}});
  const auto calibrations = store->calibrations();
  ASSERT_EQ(calibrations.size(), 2u);
  EXPECT_EQ(calibrations[1].second.session_ids, std::vector<std::int64_t>{id});
  EXPECT_EQ(calibrations[1].second.sensor_serial, "S-7");
  const auto sessions = store->sessions(host::SessionKind::kBench);
  ASSERT_EQ(sessions.size(), 1u);
  EXPECT_EQ(sessions[0].second.sensor_serial, "S-7");
  EXPECT_TRUE(store->sessions(host::SessionKind::kService).empty());
}

TEST_P(StoreTest, ASensorMovedToAnotherWheelKeepsItsHistory) {
  auto store = open();
  store->upsert_sensor({"S-1", "", WheelKey{"L", 1, "left"}, test_time(0)});
  store->record_run(test_run("L", test_time(1), 100.0, 0.1));
  store->upsert_sensor({"S-1", "", WheelKey{"L", 3, "right"}, test_time(2)});
  store->upsert_sensor({"S-1", "", WheelKey{"L", 3, "right"}, test_time(3)});  // no change
  store->record_run(test_run("L", test_time(4), 200.0, 0.2));
  const auto wheels = store->wheels();
  EXPECT_EQ(wheels[0].sensor_serial, "");     // axle 1 left: its sensor moved away
  EXPECT_EQ(wheels[5].sensor_serial, "S-1");  // axle 3 right
  const auto before = store->wear_history({"L", 1, "left"});
  EXPECT_EQ(before[0].sensor_serial, "S-1");
  EXPECT_EQ(store->wear_history({"L", 3, "right"})[1].sensor_serial, "S-1");
}

TEST_P(StoreTest, RecordsABatchOfRunsInOneCallInTheirOrder) {
  auto store = open();
  std::vector<host::RunRecord> runs;
  for (int k = 0; k < 5; ++k) {
    runs.push_back(test_run(k % 2 ? "odd" : "even", test_time(k), 100.0 * (k + 1), 0.1 * k));
    runs.back().session = host::SessionRecord{host::SessionKind::kService,
                                              "day " + std::to_string(k),
                                              test_time(k),
                                              100.0,
                                              "loco.json",
                                              "h" + std::to_string(k),
                                              ""};
  }
  const auto ids = store->record_runs(runs);
  ASSERT_EQ(ids.size(), 5u);
  EXPECT_TRUE(std::is_sorted(ids.begin(), ids.end()));
  EXPECT_EQ(store->run_count(), 5u);
  const auto odd = store->wear_history({"odd", 1, "right"});
  ASSERT_EQ(odd.size(), 2u);
  EXPECT_EQ(odd[1].run_id, ids[3]);
  EXPECT_DOUBLE_EQ(odd[1].odometer_km, 400.0);
  EXPECT_DOUBLE_EQ(odd[1].wear_mm.value(), 0.3 + 0.01);
  EXPECT_EQ(store->run_trace(ids[4]).size(), 36u);
  EXPECT_EQ(store->sessions(host::SessionKind::kService).size(), 5u);
}

INSTANTIATE_TEST_SUITE_P(Backends, StoreTest,
                         ::testing::Values(StoreBackendUnderTest::kSqlite,
                                           StoreBackendUnderTest::kPostgresql),
                         backend_param_name);

}  // namespace
}  // namespace flange::testing
