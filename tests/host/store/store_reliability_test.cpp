// SPDX-License-Identifier: MIT
// The store under trouble, on both backends: writers at once, a writer killed in the middle of
// a run, a write that fails half-way, a newer and an older schema.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <optional>
#include <thread>

#include "store_migration.h"
#include "store_test_backends.h"
#include "store_test_fixture.h"
#include "store_test_records.h"

namespace flange::testing {
namespace {

class StoreUnderTroubleTest : public StoreTest {};

// Runs `body` in a child process; returns its pid. The child exits 0 when body returns, 1 when
// it throws (the parent checks the status).
template <typename Body>
pid_t in_child(Body&& body) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    int status = 0;
    try {
      body();
    } catch (...) {
      status = 1;
    }
    ::_exit(status);
  }
  return pid;
}

int exit_status_of(pid_t pid) {
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

TEST_P(StoreUnderTroubleTest, TwoProcessesWritingRunsAtOnceLoseNothing) {
  open();  // the schema exists before the writers start
  constexpr int kRuns = 25;
  std::vector<pid_t> writers;
  for (const char* locomotive : {"A", "B"}) {
    writers.push_back(in_child([&] {
      auto store = open();
      for (int day = 0; day < kRuns; ++day) {
        store->record_run(test_run(locomotive, test_time(day % 28, day / 28), 100.0 * day, 0.01));
      }
    }));
  }
  for (const pid_t writer : writers) EXPECT_EQ(exit_status_of(writer), 0);
  auto store = open();
  EXPECT_EQ(store->run_count(), 2u * kRuns);
  EXPECT_EQ(store->wear_history({"A", 6, "right"}).size(), static_cast<std::size_t>(kRuns));
  EXPECT_EQ(store->wear_history({"B", 1, "left"}).size(), static_cast<std::size_t>(kRuns));
  EXPECT_EQ(store->alarm_events("").size(), 4u * kRuns);
}

TEST_P(StoreUnderTroubleTest, AWriterKilledInTheMiddleOfARunLeavesTheStoreAsItWas) {
  open()->record_run(test_run("K", test_time(0), 100.0, 0.1));
  const auto marker =
      std::filesystem::temp_directory_path() / ("flange_store_pause_" + std::to_string(::getpid()));
  std::filesystem::remove(marker);
  const pid_t writer = in_child([&] {
    ::setenv("FLANGE_STORE_PAUSE_BEFORE_COMMIT", marker.c_str(), 1);
    open()->record_run(test_run("K", test_time(1), 200.0, 0.2));
  });
  for (int waited = 0; waited < 300 && !std::filesystem::exists(marker); ++waited) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  ASSERT_TRUE(std::filesystem::exists(marker)) << "the writer never reached its pause";
  ::kill(writer, SIGKILL);
  EXPECT_EQ(exit_status_of(writer), 128 + SIGKILL);
  std::filesystem::remove(marker);

  auto store = open();
  EXPECT_EQ(store->run_count(), 1u);
  EXPECT_EQ(store->wear_history({"K", 1, "left"}).size(), 1u);
  EXPECT_EQ(store->alarm_events("K").size(), 2u);
  // The killed writer's locks are gone: the next run is written at once.
  store->record_run(test_run("K", test_time(2), 300.0, 0.3));
  EXPECT_EQ(store->run_count(), 2u);
}

TEST_P(StoreUnderTroubleTest, ARunThatFailsHalfWayWritesNothing) {
  auto store = open();
  auto run = test_run("F", test_time(0), 100.0, 0.1);
  run.wheels[7].side = "middle";  // refused by the schema after seven wheels are written
  EXPECT_THROW(store->record_run(run), host::StoreError);
  EXPECT_EQ(store->run_count(), 0u);
  EXPECT_TRUE(store->wheels().empty());
  EXPECT_TRUE(store->locomotives().empty());
  EXPECT_TRUE(store->alarm_events("").empty());
  // A batch whose last run is refused: none of it is written.
  std::vector<host::RunRecord> batch = {test_run("G", test_time(1), 1.0, 0.1), run};
  EXPECT_THROW(store->record_runs(batch), host::StoreError);
  EXPECT_EQ(store->run_count(), 0u);
  EXPECT_TRUE(store->locomotives().empty());
}

TEST_P(StoreUnderTroubleTest, AStoreOfANewerSchemaIsRefusedUnchanged) {
  open()->record_run(test_run("N", test_time(0), 100.0, 0.1));
  execute_sql(url(), "UPDATE schema_version SET version = 99");
  try {
    open();
    FAIL() << "a newer store was opened";
  } catch (const host::StoreError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("schema version 99 is newer than this flange's"), std::string::npos)
        << message;
    EXPECT_EQ(message.find('\n'), std::string::npos);
  }
  execute_sql(url(),
              "UPDATE schema_version SET version = " + std::to_string(host::kStoreSchemaVersion));
  EXPECT_EQ(open()->run_count(), 1u);
}

TEST_P(StoreUnderTroubleTest, AnOlderStoreIsMigratedKeepingItsRows) {
  EXPECT_EQ(host::open_store_at_schema_version(url(), 1)->schema_version(), 1);
  execute_sql(url(), "INSERT INTO locomotives (name, description) VALUES ('old', 'from v1')");
  auto store = open();
  EXPECT_EQ(store->schema_version(), host::kStoreSchemaVersion);
  EXPECT_EQ(store->locomotives().at(0).description, "from v1");
  const auto run = store->record_run(test_run("old", test_time(0), 1.0, 0.1));  // needs v2
  EXPECT_EQ(store->run_trace(run).size(), 36u);
}

// A version 2 store (no per-wheel sums) opens: migration 3 fills the sums from its runs, and the
// writes keep them from then on.
TEST_P(StoreUnderTroubleTest, AVersion2StoreGetsItsFleetSumsFromItsRuns) {
  {
    const auto old = host::open_store_at_schema_version(url(), 2);
    write_mixed_history(*old);
  }
  auto store = open();
  EXPECT_EQ(store->schema_version(), host::kStoreSchemaVersion);
  expect_fleet_table_matches_runs(*store);
  store->record_run(test_run("N", test_time(12), 9900.0, 1.2));
  store->record_maintenance(
      {{"N", 2, "right"}, test_time(10), 9000.0, "reprofile", "after", std::nullopt});
  expect_fleet_table_matches_runs(*store);
}

// A store of every older version holds a wheelset move's source axle in the event's note, as the
// flange of that version wrote it ("from axle N" or "from axle N; the depot's note"): opened, it
// is migrated to the from_axle column and the note keeps the depot's words. Notes in any other
// form, and the notes of other kinds of event, are kept as they are, with no source axle.
TEST_P(StoreUnderTroubleTest, AnOlderStoresWheelsetMovesGetTheirSourceAxleFromTheirNotes) {
  for (int version = 1; version < host::kFromAxleSchemaVersion; ++version) {
    SCOPED_TRACE("a store of schema version " + std::to_string(version));
    const std::string old_url = fresh_store_url(GetParam(), "moves_v" + std::to_string(version));
    {
      const auto old = host::open_store_at_schema_version(old_url, version);
      old->record_maintenance({{"W", 1, "left"}, test_time(1), 100.0, "wheelset_moved", "", 3});
      old->record_maintenance(
          {{"W", 2, "left"}, test_time(2), 200.0, "wheelset_moved", "after a flat; see log", 5});
      old->record_maintenance({{"W", 3, "left"},
                               test_time(3),
                               300.0,
                               "reprofile",
                               "from axle 2; not a move",
                               std::nullopt});
      old->record_maintenance(
          {{"W", 4, "left"}, test_time(4), 400.0, "wheelset_moved", "from axle 12", std::nullopt});
      old->record_maintenance(
          {{"W", 5, "left"}, test_time(5), 500.0, "wheelset_moved", "by hand", std::nullopt});
      EXPECT_EQ(old->maintenance_events("W").at(0).event.note, "from axle 3");
    }
    const auto store = host::open_store(old_url);
    ASSERT_EQ(store->schema_version(), host::kStoreSchemaVersion);
    const auto events = store->maintenance_events("W");
    ASSERT_EQ(events.size(), 5u);
    const std::pair<std::optional<int>, std::string> expected[] = {
        {3, ""},
        {5, "after a flat; see log"},
        {std::nullopt, "from axle 2; not a move"},
        {std::nullopt, "from axle 12"},
        {std::nullopt, "by hand"}};
    for (std::size_t i = 0; i < events.size(); ++i) {
      EXPECT_EQ(events[i].event.from_axle, expected[i].first) << "event " << i;
      EXPECT_EQ(events[i].event.note, expected[i].second) << "event " << i;
    }
  }
}

TEST_P(StoreUnderTroubleTest, ATableThatIsNotAFlangeStoreIsRefused) {
  execute_sql(url(), "CREATE TABLE somebody_elses (x INTEGER)");
  EXPECT_THROW(open(), host::StoreError);
}

INSTANTIATE_TEST_SUITE_P(Backends, StoreUnderTroubleTest,
                         ::testing::Values(StoreBackendUnderTest::kSqlite,
                                           StoreBackendUnderTest::kPostgresql),
                         backend_param_name);

}  // namespace
}  // namespace flange::testing
