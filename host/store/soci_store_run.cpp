// SPDX-License-Identifier: MIT
// record_run: a run, its wheels' results, alarm events and reduced trace in one transaction.
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <thread>

#include "column_batch.h"
#include "soci_store.h"
#include "store_transaction.h"
#include "wheel_fit_batch.h"
#include "wheel_fit_table.h"

namespace flange::host {

namespace {

using soci::into;
using soci::use;

// A test hook (docs/store.md): with FLANGE_STORE_PAUSE_BEFORE_COMMIT=FILE, record_run writes
// FILE once its rows are written but not committed, then waits a minute, so that a test can
// kill the process in the middle of the write.
void pause_for_test() {
  const char* marker = std::getenv("FLANGE_STORE_PAUSE_BEFORE_COMMIT");
  if (marker == nullptr || *marker == '\0') return;
  std::ofstream(marker) << "paused\n";
  std::this_thread::sleep_for(std::chrono::seconds(60));
}

}  // namespace

std::optional<long long> SociStore::event_wheel(const RunRecord& run, int axle,
                                                const std::string& side, WheelIds& created) {
  if (run.locomotive.empty() || axle == 0) return std::nullopt;
  const WheelKey key{run.locomotive, axle, side};
  return wheel_id(key, default_channel(key), created);
}

// The rows of a batch of runs below their run rows, written after the runs with one
// statement per table (column_batch.h).
struct SociStore::RunBatches {
  ColumnBatch wheel_runs{"wheel_runs",
                         {{"run_id", "BIGINT"},
                          {"wheel_id", "BIGINT"},
                          {"channel", "INTEGER"},
                          {"started_at", "TEXT"},
                          {"odometer_km", "DOUBLE PRECISION"},
                          {"wear_mm", "DOUBLE PRECISION"},
                          {"clearance_mm", "DOUBLE PRECISION"},
                          {"temp_c", "DOUBLE PRECISION"},
                          {"samples", "BIGINT"},
                          {"flagged_samples", "BIGINT"},
                          {"final_alarm", "TEXT"},
                          {"mae_before_mm", "DOUBLE PRECISION"},
                          {"mae_after_mm", "DOUBLE PRECISION"}}};
  ColumnBatch alarm_events{"alarm_events",
                           {{"run_id", "BIGINT"},
                            {"wheel_id", "BIGINT"},
                            {"t_s", "DOUBLE PRECISION"},
                            {"what", "TEXT"}}};
  ColumnBatch run_trace{"run_trace",
                        {{"run_id", "BIGINT"},
                         {"wheel_id", "BIGINT"},
                         {"km", "DOUBLE PRECISION"},
                         {"clearance_mm", "DOUBLE PRECISION"},
                         {"temp_c", "DOUBLE PRECISION"},
                         {"samples", "BIGINT"}}};
  WheelFitBatch fit;  // what the batch adds to its wheels' wheel_fit rows

  void flush(soci::session& sql, StoreBackend backend) {
    wheel_runs.flush(sql, backend);
    alarm_events.flush(sql, backend);
    run_trace.flush(sql, backend);
  }
};

void SociStore::add_wheel_runs(long long run_id, const RunRecord& run, WheelIds& created,
                               RunBatches& batches) {
  if (run.wheels.empty()) return;
  if (run.locomotive.empty()) {
    throw StoreError("store " + url_.shown + ": a run with wheel results names no locomotive");
  }
  ColumnBatch& rows = batches.wheel_runs;
  for (const WheelRunResult& wheel : run.wheels) {
    const long long wheel_row =
        wheel_id({run.locomotive, wheel.axle, wheel.side}, wheel.channel, created);
    batches.fit.add_run(wheel_row, run.started_at, run_id, run.odometer_km, wheel.wear_mm);
    rows.add(run_id);
    rows.add(wheel_row);
    rows.add(static_cast<long long>(wheel.channel));
    rows.add(run.started_at);
    rows.add(run.odometer_km);
    rows.add(wheel.wear_mm);
    rows.add(wheel.clearance_mm);
    rows.add(wheel.temp_c);
    rows.add(static_cast<long long>(wheel.samples));
    rows.add(static_cast<long long>(wheel.flagged_samples));
    rows.add(wheel.final_alarm);
    rows.add(wheel.mae_before_mm);
    rows.add(wheel.mae_after_mm);
  }
}

void SociStore::add_alarm_events(long long run_id, const RunRecord& run, WheelIds& created,
                                 RunBatches& batches) {
  for (const AlarmEventRecord& event : run.alarms) {
    const std::optional<long long> wheel = event_wheel(run, event.axle, event.side, created);
    if (wheel) batches.fit.add_alarm(*wheel);
    batches.alarm_events.add(run_id);
    batches.alarm_events.add(wheel);
    batches.alarm_events.add(event.t_s);
    batches.alarm_events.add(event.what);
  }
}

void SociStore::add_trace(long long run_id, const RunRecord& run, WheelIds& created,
                          RunBatches& batches) {
  for (const TracePoint& point : run.trace) {
    batches.run_trace.add(run_id);
    batches.run_trace.add(event_wheel(run, point.axle, point.side, created));
    batches.run_trace.add(point.km);
    batches.run_trace.add(point.clearance_mm);
    batches.run_trace.add(point.temp_c);
    batches.run_trace.add(static_cast<long long>(point.samples));
  }
}

long long SociStore::insert_run_row(const RunRecord& run, WheelIds& created) {
  std::optional<long long> locomotive;
  if (!run.locomotive.empty()) locomotive = locomotive_id(run.locomotive, created);
  long long locomotive_value = locomotive.value_or(0);
  soci::indicator has_locomotive = locomotive ? soci::i_ok : soci::i_null;
  std::optional<long long> session = run.session_id;
  if (!session && run.session) session = insert_session(*run.session, {});
  long long session_value = session.value_or(0);
  soci::indicator has_session = session ? soci::i_ok : soci::i_null;
  long long calibration_value = run.calibration_id.value_or(0);
  soci::indicator has_calibration = run.calibration_id ? soci::i_ok : soci::i_null;
  const auto rows = static_cast<long long>(run.rows);
  const auto flagged = static_cast<long long>(run.flagged_rows);
  const auto bad = static_cast<long long>(run.bad_rows);
  long long id = 0;
  sql_ << "INSERT INTO runs (locomotive_id, session_id, started_at, distance_km, odometer_km,"
          " coefficient_set, coefficient_sha256, calibration_id, engine, sample_rate_hz,"
          " rows_read, flagged_rows, bad_rows, final_alarm, summary_json) VALUES (:locomotive,"
          " :session, :at, :distance, :odometer, :coefficients, :coefficients_sha, :calibration,"
          " :engine, :fs, :rows, :flagged, :bad, :alarm, :summary) RETURNING id",
      use(locomotive_value, has_locomotive), use(session_value, has_session), use(run.started_at),
      use(run.distance_km), use(run.odometer_km), use(run.coefficient_set),
      use(run.coefficient_sha256), use(calibration_value, has_calibration), use(run.engine),
      use(run.sample_rate_hz), use(rows), use(flagged), use(bad), use(run.final_alarm),
      use(run.summary_json), into(id);
  return id;
}

long long SociStore::insert_run(const RunRecord& run, WheelIds& created, RunBatches& batches) {
  const long long id = insert_run_row(run, created);
  add_wheel_runs(id, run, created, batches);
  add_alarm_events(id, run, created, batches);
  add_trace(id, run, created, batches);
  return id;
}

std::vector<long long> SociStore::insert_run_rows(const std::vector<RunRecord>& runs,
                                                  WheelIds& created) {
  std::vector<long long> ids;
  if (url_.backend == StoreBackend::kSqlite) {
    for (const RunRecord& run : runs) ids.push_back(insert_run_row(run, created));
    return ids;
  }
  ColumnBatch rows("runs", {{"locomotive_id", "BIGINT"},
                            {"session_id", "BIGINT"},
                            {"started_at", "TEXT"},
                            {"distance_km", "DOUBLE PRECISION"},
                            {"odometer_km", "DOUBLE PRECISION"},
                            {"coefficient_set", "TEXT"},
                            {"coefficient_sha256", "TEXT"},
                            {"calibration_id", "BIGINT"},
                            {"engine", "TEXT"},
                            {"sample_rate_hz", "DOUBLE PRECISION"},
                            {"rows_read", "BIGINT"},
                            {"flagged_rows", "BIGINT"},
                            {"bad_rows", "BIGINT"},
                            {"final_alarm", "TEXT"},
                            {"summary_json", "TEXT"}});
  for (const RunRecord& run : runs) {
    std::optional<long long> locomotive, session = run.session_id;
    if (!run.locomotive.empty()) locomotive = locomotive_id(run.locomotive, created);
    if (!session && run.session) session = insert_session(*run.session, {});
    rows.add(locomotive);
    rows.add(session);
    rows.add(run.started_at);
    rows.add(run.distance_km);
    rows.add(run.odometer_km);
    rows.add(run.coefficient_set);
    rows.add(run.coefficient_sha256);
    rows.add(run.calibration_id ? std::optional<long long>(*run.calibration_id) : std::nullopt);
    rows.add(run.engine);
    rows.add(run.sample_rate_hz);
    rows.add(static_cast<long long>(run.rows));
    rows.add(static_cast<long long>(run.flagged_rows));
    rows.add(static_cast<long long>(run.bad_rows));
    rows.add(run.final_alarm);
    rows.add(run.summary_json);
  }
  return rows.flush_returning_ids(sql_);
}

std::int64_t SociStore::record_run(const RunRecord& run) {
  return store_guarded(url_.shown, "recording a run", [&]() -> std::int64_t {
    WriteTransaction transaction(sql_, url_.backend);
    WheelIds created;
    RunBatches batches;
    const long long id = insert_run(run, created, batches);
    batches.flush(sql_, url_.backend);
    if (schema_version_ >= kWheelFitSchemaVersion) batches.fit.apply(sql_, url_.backend);
    pause_for_test();
    transaction.commit();
    wheel_ids_.insert(created.begin(), created.end());
    return id;
  });
}

std::vector<std::int64_t> SociStore::record_runs(const std::vector<RunRecord>& runs) {
  return store_guarded(url_.shown, "recording runs", [&] {
    std::vector<std::int64_t> ids;
    WriteTransaction transaction(sql_, url_.backend);
    WheelIds created;
    RunBatches batches;
    const std::vector<long long> run_ids = insert_run_rows(runs, created);
    for (std::size_t i = 0; i < runs.size(); ++i) {
      add_wheel_runs(run_ids[i], runs[i], created, batches);
      add_alarm_events(run_ids[i], runs[i], created, batches);
      add_trace(run_ids[i], runs[i], created, batches);
      ids.push_back(run_ids[i]);
    }
    batches.flush(sql_, url_.backend);
    if (schema_version_ >= kWheelFitSchemaVersion) batches.fit.apply(sql_, url_.backend);
    pause_for_test();
    transaction.commit();
    wheel_ids_.insert(created.begin(), created.end());
    return ids;
  });
}

}  // namespace flange::host
