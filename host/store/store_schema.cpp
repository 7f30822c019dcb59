// SPDX-License-Identifier: MIT
#include "store_schema.h"

#include <fmt/format.h>

#include <vector>

#include "store.h"
#include "store_transaction.h"
#include "wheel_fit_table.h"

namespace flange::host {

namespace {

// Written once for both backends; {id} and {real} are the two words they spell differently.
// 1: the fleet, its sensors, sessions, calibrations, runs and what they found.
std::vector<std::string> migration_1() {
  return {
      "CREATE TABLE schema_version (version INTEGER NOT NULL)",
      "INSERT INTO schema_version (version) VALUES (0)",
      "CREATE TABLE locomotives (id {id}, name TEXT NOT NULL UNIQUE,"
      " description TEXT NOT NULL DEFAULT '')",
      "CREATE TABLE wheels (id {id},"
      " locomotive_id BIGINT NOT NULL REFERENCES locomotives (id),"
      " axle INTEGER NOT NULL CHECK (axle BETWEEN 1 AND 6),"
      " side TEXT NOT NULL CHECK (side IN ('left', 'right')),"
      " channel INTEGER NOT NULL CHECK (channel BETWEEN 0 AND 11),"
      " UNIQUE (locomotive_id, axle, side))",
      "CREATE TABLE sensors (id {id}, serial TEXT NOT NULL UNIQUE,"
      " model TEXT NOT NULL DEFAULT '')",
      "CREATE TABLE sensor_fitments (id {id},"
      " sensor_id BIGINT NOT NULL REFERENCES sensors (id),"
      " wheel_id BIGINT NOT NULL REFERENCES wheels (id), fitted_at TEXT NOT NULL)",
      "CREATE TABLE sessions (id {id},"
      " kind TEXT NOT NULL CHECK (kind IN ('bench', 'service')), label TEXT NOT NULL,"
      " started_at TEXT NOT NULL, sample_rate_hz {real} NOT NULL,"
      " source_file TEXT NOT NULL, source_sha256 TEXT NOT NULL,"
      " sensor_id BIGINT REFERENCES sensors (id),"
      " UNIQUE (kind, label, source_sha256))",
      "CREATE TABLE bench_rows (session_id BIGINT NOT NULL REFERENCES sessions (id),"
      " seq INTEGER NOT NULL, t_s {real} NOT NULL, clearance_mm {real},"
      " temp_c {real} NOT NULL, voltage_v {real} NOT NULL, PRIMARY KEY (session_id, seq))",
      "CREATE TABLE calibrations (id {id}, fitted_at TEXT NOT NULL,"
      " sensor_id BIGINT REFERENCES sensors (id), model_json TEXT NOT NULL,"
      " fitted_rows BIGINT NOT NULL, rmse_mm {real} NOT NULL)",
      "CREATE TABLE calibration_sessions ("
      " calibration_id BIGINT NOT NULL REFERENCES calibrations (id),"
      " session_id BIGINT NOT NULL REFERENCES sessions (id),"
      " PRIMARY KEY (calibration_id, session_id))",
      "CREATE TABLE runs (id {id}, locomotive_id BIGINT REFERENCES locomotives (id),"
      " session_id BIGINT REFERENCES sessions (id), started_at TEXT NOT NULL,"
      " distance_km {real} NOT NULL, odometer_km {real} NOT NULL,"
      " coefficient_set TEXT NOT NULL, coefficient_sha256 TEXT NOT NULL,"
      " calibration_id BIGINT REFERENCES calibrations (id), engine TEXT NOT NULL,"
      " sample_rate_hz {real} NOT NULL, rows_read BIGINT NOT NULL,"
      " flagged_rows BIGINT NOT NULL, bad_rows BIGINT NOT NULL,"
      " final_alarm TEXT NOT NULL, summary_json TEXT NOT NULL)",
      // The run's time and odometer are repeated here: a wheel's history and the fleet table
      // read this one table (by wheel and time) without joining the runs.
      "CREATE TABLE wheel_runs (run_id BIGINT NOT NULL REFERENCES runs (id),"
      " wheel_id BIGINT NOT NULL REFERENCES wheels (id), channel INTEGER NOT NULL,"
      " started_at TEXT NOT NULL, odometer_km {real} NOT NULL,"
      " wear_mm {real}, clearance_mm {real}, temp_c {real} NOT NULL,"
      " samples BIGINT NOT NULL, flagged_samples BIGINT NOT NULL,"
      " final_alarm TEXT NOT NULL, mae_before_mm {real}, mae_after_mm {real},"
      " PRIMARY KEY (run_id, wheel_id))",
      "CREATE TABLE alarm_events (id {id}, run_id BIGINT NOT NULL REFERENCES runs (id),"
      " wheel_id BIGINT REFERENCES wheels (id), t_s {real} NOT NULL, what TEXT NOT NULL)",
      "CREATE TABLE maintenance_events (id {id},"
      " wheel_id BIGINT NOT NULL REFERENCES wheels (id), at TEXT NOT NULL,"
      " odometer_km {real} NOT NULL, kind TEXT NOT NULL, note TEXT NOT NULL)",
  };
}

// 2: the reduced trace of service runs, and the indexes the wear queries use.
std::vector<std::string> migration_2() {
  return {
      "CREATE TABLE run_trace (run_id BIGINT NOT NULL REFERENCES runs (id),"
      " wheel_id BIGINT REFERENCES wheels (id), km {real} NOT NULL,"
      " clearance_mm {real} NOT NULL, temp_c {real} NOT NULL, samples BIGINT NOT NULL)",
      "CREATE INDEX run_trace_by_run ON run_trace (run_id)",
      "CREATE INDEX wheel_runs_by_wheel ON wheel_runs (wheel_id, started_at)",
      "CREATE INDEX runs_by_locomotive ON runs (locomotive_id, started_at)",
      "CREATE INDEX alarm_events_by_run ON alarm_events (run_id)",
      "CREATE INDEX alarm_events_by_wheel ON alarm_events (wheel_id)",
      "CREATE INDEX maintenance_by_wheel ON maintenance_events (wheel_id, at)",
      "CREATE INDEX fitments_by_wheel ON sensor_fitments (wheel_id, fitted_at)",
  };
}

// 3: the fleet table's per-wheel sums, kept by the writes (wheel_fit_table.h), filled from the
// runs already stored.
std::vector<std::string> migration_3() { return wheel_fit_migration(); }

// 4: the wear estimates `flange wear` keeps (soci_store_estimates.cpp), from which a
// reprofiling plan is made without reading every run again: the settings and the store's latest
// ids when they were made, and one row per wheel.
std::vector<std::string> migration_4() {
  return {
      "CREATE TABLE wear_estimates (made_at TEXT NOT NULL, last_run_id BIGINT NOT NULL,"
      " last_maintenance_id BIGINT NOT NULL, last_calibration_id BIGINT NOT NULL,"
      " warning_clearance_mm {real} NOT NULL, critical_clearance_mm {real} NOT NULL,"
      " max_step_mm {real} NOT NULL)",
      "CREATE TABLE wheel_estimates (wheel_id BIGINT PRIMARY KEY REFERENCES wheels (id),"
      " status TEXT NOT NULL, has_fit INTEGER NOT NULL, segment_start TEXT NOT NULL,"
      " last_run_at TEXT NOT NULL, last_run_day {real}, rate {real}, rate_low {real},"
      " rate_high {real}, rate_se {real}, rate_dof INTEGER NOT NULL, fit_dof INTEGER NOT NULL,"
      " clearance_now_mm {real}, wear_now_mm {real}, km_per_day {real}, km_per_day_se {real},"
      " day_km_sd {real}, km_per_day_dof INTEGER NOT NULL, clearance_now_se_mm {real},"
      " clearance_rate_covariance {real}, critical_reached INTEGER NOT NULL,"
      " critical_date TEXT NOT NULL, warning_date TEXT NOT NULL)",
  };
}

// 5: a wheelset move's source axle as data. Older stores wrote it into the note, as
// "from axle N" or "from axle N; the depot's note" (nothing else wrote that form): it moves to
// the column and the note keeps the depot's words only. A note in any other form is left as it
// is, with no source axle.
std::vector<std::string> migration_5() {
  const std::string old_form =
      " WHERE kind = 'wheelset_moved' AND SUBSTR(note, 1, 10) = 'from axle '"
      " AND SUBSTR(note, 11, 1) IN ('1', '2', '3', '4', '5', '6')"
      " AND (LENGTH(note) = 11 OR SUBSTR(note, 12, 2) = '; ')";
  return {
      "ALTER TABLE maintenance_events ADD COLUMN from_axle INTEGER"
      " CHECK (from_axle BETWEEN 1 AND 6)",
      "UPDATE maintenance_events SET from_axle = CAST(SUBSTR(note, 11, 1) AS INTEGER),"
      " note = CASE WHEN LENGTH(note) = 11 THEN '' ELSE SUBSTR(note, 14) END" +
          old_form,
  };
}

// 6: each wheel's sensor flag, carried by the wear estimates from one `flange wear` to the next
// (host/wear/sensor_flag_latch.h): when it was first flagged and when confirmed ('' for none).
std::vector<std::string> migration_6() {
  return {
      "ALTER TABLE wheel_estimates ADD COLUMN sensor_flag_first TEXT NOT NULL DEFAULT ''",
      "ALTER TABLE wheel_estimates ADD COLUMN sensor_flag_confirmed TEXT NOT NULL DEFAULT ''",
  };
}

// 7: the dates' whole forecast input, so the plan from the stored estimates is the same
// quantile of the same forecast (host/wear/reprofiling_plan.h, PlanInput): JSON, written and
// read by cli/stored_wear_estimates.cpp. '' in the rows written before: planned on the rate's
// quantile alone, as they were then.
std::vector<std::string> migration_7() {
  return {
      "ALTER TABLE wheel_estimates ADD COLUMN forecast TEXT NOT NULL DEFAULT ''",
  };
}

// Migration N is migrations()[N - 1]; kStoreSchemaVersion is their count.
const std::vector<std::vector<std::string>>& migrations() {
  static const std::vector<std::vector<std::string>> steps = {
      migration_1(), migration_2(), migration_3(), migration_4(),
      migration_5(), migration_6(), migration_7()};
  return steps;
}

std::string in_dialect(std::string statement, StoreBackend backend) {
  const bool sqlite = backend == StoreBackend::kSqlite;
  const std::pair<std::string, std::string> words[] = {
      {"{id}",
       sqlite ? "INTEGER PRIMARY KEY" : "BIGINT GENERATED BY DEFAULT AS IDENTITY PRIMARY KEY"},
      {"{real}", sqlite ? "REAL" : "DOUBLE PRECISION"}};
  for (const auto& [word, spelling] : words) {
    for (auto at = statement.find(word); at != std::string::npos; at = statement.find(word)) {
      statement.replace(at, word.size(), spelling);
    }
  }
  return statement;
}

int count_of(soci::session& sql, const std::string& query) {
  long long count = 0;
  sql << query, soci::into(count);
  return static_cast<int>(count);
}

}  // namespace

int stored_schema_version(soci::session& sql, const StoreUrl& url) {
  const bool sqlite = url.backend == StoreBackend::kSqlite;
  const std::string tables = sqlite ? "SELECT COUNT(*) FROM sqlite_master WHERE type = 'table'"
                                    : "SELECT COUNT(*) FROM information_schema.tables"
                                      " WHERE table_schema = current_schema()";
  if (count_of(sql, tables) == 0) return 0;
  const int has_version =
      count_of(sql, tables + " AND " + (sqlite ? "name" : "table_name") + " = 'schema_version'");
  if (has_version == 0) {
    throw StoreError("store " + url.shown + ": holds tables but is not a flange store");
  }
  long long version = 0;
  sql << "SELECT MAX(version) FROM schema_version", soci::into(version);
  return static_cast<int>(version);
}

void migrate_store(soci::session& sql, const StoreUrl& url, int target) {
  WriteTransaction transaction(sql, url.backend);
  // Two processes opening a new PostgreSQL store at once: the second waits, then finds it made.
  if (url.backend == StoreBackend::kPostgresql) sql << "SELECT pg_advisory_xact_lock(727361)";
  const int version = stored_schema_version(sql, url);
  if (version > target) {
    throw StoreError(fmt::format(
        "store {}: schema version {} is newer than this flange's {}; use a newer flange", url.shown,
        version, target));
  }
  if (version == target) return;  // rolled back: nothing was written
  const auto& steps = migrations();
  for (int next = version + 1; next <= target; ++next) {
    for (const std::string& statement : steps.at(static_cast<std::size_t>(next - 1))) {
      sql << in_dialect(statement, url.backend);
    }
    sql << "UPDATE schema_version SET version = :v", soci::use(next);
  }
  transaction.commit();
}

}  // namespace flange::host
