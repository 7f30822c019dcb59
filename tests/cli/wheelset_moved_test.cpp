// SPDX-License-Identifier: MIT
// A wheelset moved to another axle, on SQLite and PostgreSQL: `flange maintenance --kind
// wheelset_moved --from-axle N` stores the source axle as data and the note as given, and the
// wear of the moved wheelset's runs (fill_wheel_wear, as `flange run --store` fills it) carries
// on from the axle it ran on: in a new store, and in one of schema version 4 whose move was
// written the way that version wrote it (in the note) and then migrated.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "flange_in_process.h"
#include "store.h"
#include "store_migration.h"
#include "store_test_backends.h"
#include "store_test_fixture.h"
#include "store_test_records.h"
#include "wheel_wear_reference.h"

namespace flange::cli {
namespace {

using testing::command_text;
using testing::FlangeOutcome;
using testing::fresh_store_url;
using testing::run_flange_captured;
using testing::StoreBackendUnderTest;
using testing::test_run;
using testing::test_time;

constexpr double kNewFlangeClearanceMm = 2.0;

class WheelsetMoved : public ::testing::TestWithParam<StoreBackendUnderTest> {
 protected:
  std::string url(const std::string& name) const {
    return fresh_store_url(GetParam(),
                           ::testing::UnitTest::GetInstance()->current_test_info()->name() + name);
  }
};

// A run of locomotive "L" on `day` whose wheel on axle 1 left reads `clearance_mm`.
host::RunRecord run_with_axle_1_left(int day, double clearance_mm) {
  host::RunRecord run = test_run("L", test_time(day), 1000.0 * day, 0.0);
  run.wheels.front().clearance_mm = clearance_mm;
  return run;
}

// Runs on days 0 to 2 (axle 3 left has worn 0.2 * day + 0.04 mm by test_run's pattern), the
// wheelset of axle 3 moved to axle 1 on day 3, then axle 1 left's first two runs after the move
// at 5.0 and 5.1 mm: its wear is axle 3 left's last before the move, then 0.1 mm more.
void expect_wear_carried_from_axle_3(host::Store& store) {
  for (int day = 0; day < 3; ++day)
    store.record_run(test_run("L", test_time(day), 1000.0 * day, 0.2 * day));
  const double carried = 0.2 * 2 + 0.01 * 4;  // axle 3 left is channel 4
  host::RunRecord first = run_with_axle_1_left(4, 5.0);
  fill_wheel_wear(store, first, kNewFlangeClearanceMm);
  EXPECT_NEAR(first.wheels.front().wear_mm.value(), carried, 1e-12);
  store.record_run(first);
  host::RunRecord second = run_with_axle_1_left(5, 5.1);
  fill_wheel_wear(store, second, kNewFlangeClearanceMm);
  EXPECT_NEAR(second.wheels.front().wear_mm.value(), carried + 0.1, 1e-12);
  // Axle 1 right was not moved by this event: its wear is against the new flange.
  EXPECT_NEAR(second.wheels[1].wear_mm.value(),
              second.wheels[1].clearance_mm.value() - kNewFlangeClearanceMm, 1e-12);
}

TEST_P(WheelsetMoved, FlangeMaintenanceStoresTheSourceAxleAndTheNoteAsGiven) {
  const std::string store = url("");
  const std::vector<std::string> args = {"maintenance",
                                         "--store",
                                         store,
                                         "--locomotive",
                                         "L",
                                         "--kind",
                                         "wheelset_moved",
                                         "--axle",
                                         "1",
                                         "--side",
                                         "left",
                                         "--from-axle",
                                         "3",
                                         "--at",
                                         test_time(3),
                                         "--note",
                                         "after a flat; see the log"};
  const FlangeOutcome outcome = run_flange_captured(args);
  ASSERT_EQ(outcome.status, 0) << command_text(args) << "\n" << outcome.err;
  const auto opened = host::open_store(store);
  const auto events = opened->maintenance_events("L");
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].event.from_axle, 3);
  EXPECT_EQ(events[0].event.note, "after a flat; see the log");
  expect_wear_carried_from_axle_3(*opened);
}

TEST_P(WheelsetMoved, AMoveStoredByAVersion4StoreCarriesTheWearOnceMigrated) {
  const std::string store = url("");
  {
    const auto old = host::open_store_at_schema_version(store, 4);
    old->record_maintenance({{"L", 1, "left"}, test_time(3), 3000.0, "wheelset_moved", "", 3});
    EXPECT_EQ(old->maintenance_events("L").at(0).event.note, "from axle 3");
  }
  const auto opened = host::open_store(store);
  ASSERT_EQ(opened->schema_version(), host::kStoreSchemaVersion);
  expect_wear_carried_from_axle_3(*opened);
}

// Without a source axle (a move stored in a note of another form before the column existed),
// nothing is carried over: the wear is against the new flange, as for a wheel never moved.
TEST_P(WheelsetMoved, AMoveWithoutASourceAxleCarriesNothing) {
  const auto store = host::open_store(url(""));
  store->record_maintenance(
      {{"L", 1, "left"}, test_time(3), 3000.0, "wheelset_moved", "by hand", std::nullopt});
  for (int day = 0; day < 3; ++day)
    store->record_run(test_run("L", test_time(day), 1000.0 * day, 0.2 * day));
  host::RunRecord run = run_with_axle_1_left(4, 5.0);
  fill_wheel_wear(*store, run, kNewFlangeClearanceMm);
  EXPECT_NEAR(run.wheels.front().wear_mm.value(), 5.0 - kNewFlangeClearanceMm, 1e-12);
}

TEST(WheelsetMovedRefusals, ASourceAxleOutsideTheAxlesOrEqualToTheAxleIsOneLine) {
  const std::string store = fresh_store_url(StoreBackendUnderTest::kSqlite, "refusals");
  for (const char* from : {"0", "7", "2"}) {
    const std::vector<std::string> args = {
        "maintenance", "--store", store,  "--locomotive", "L",           "--kind", "wheelset_moved",
        "--axle",      "2",       "--at", test_time(3),   "--from-axle", from};
    const FlangeOutcome outcome = run_flange_captured(args);
    EXPECT_EQ(outcome.status, 2) << command_text(args) << "\n" << outcome.err;
    EXPECT_NE(outcome.err.find("--from-axle"), std::string::npos) << outcome.err;
    EXPECT_EQ(std::count(outcome.err.begin(), outcome.err.end(), '\n'), 1) << outcome.err;
  }
  EXPECT_TRUE(host::open_store(store)->maintenance_events("L").empty());
}

INSTANTIATE_TEST_SUITE_P(Backends, WheelsetMoved,
                         ::testing::Values(StoreBackendUnderTest::kSqlite,
                                           StoreBackendUnderTest::kPostgresql),
                         testing::backend_param_name);

}  // namespace
}  // namespace flange::cli
