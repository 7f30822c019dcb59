// SPDX-License-Identifier: MIT
// record_run: a run, its wheels' results, alarm events and reduced trace in one transaction.
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <thread>

#include "soci_store.h"
#include "store_transaction.h"

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

soci::indicator present(const std::optional<double>& value) {
  return value ? soci::i_ok : soci::i_null;
}

struct OptionalColumn {
  std::vector<double> values;
  std::vector<soci::indicator> present;
  void add(const std::optional<double>& value) {
    values.push_back(value.value_or(0.0));
    present.push_back(flange::host::present(value));
  }
};

}  // namespace

std::optional<long long> SociStore::event_wheel(const RunRecord& run, int axle,
                                                const std::string& side, WheelIds& created) {
  if (run.locomotive.empty() || axle == 0) return std::nullopt;
  const WheelKey key{run.locomotive, axle, side};
  return wheel_id(key, default_channel(key), created);
}

void SociStore::insert_wheel_runs(long long run_id, const RunRecord& run, WheelIds& created) {
  if (run.wheels.empty()) return;
  if (run.locomotive.empty()) {
    throw StoreError("store " + url_.shown + ": a run with wheel results names no locomotive");
  }
  std::vector<long long> run_ids, wheel_ids, samples, flagged;
  std::vector<int> channels;
  std::vector<double> temps;
  std::vector<std::string> alarms;
  OptionalColumn wear, clearance, mae_before, mae_after;
  for (const WheelRunResult& wheel : run.wheels) {
    run_ids.push_back(run_id);
    wheel_ids.push_back(wheel_id({run.locomotive, wheel.axle, wheel.side}, wheel.channel, created));
    channels.push_back(wheel.channel);
    wear.add(wheel.wear_mm);
    clearance.add(wheel.clearance_mm);
    temps.push_back(wheel.temp_c);
    samples.push_back(static_cast<long long>(wheel.samples));
    flagged.push_back(static_cast<long long>(wheel.flagged_samples));
    alarms.push_back(wheel.final_alarm);
    mae_before.add(wheel.mae_before_mm);
    mae_after.add(wheel.mae_after_mm);
  }
  sql_ << "INSERT INTO wheel_runs (run_id, wheel_id, channel, wear_mm, clearance_mm, temp_c,"
          " samples, flagged_samples, final_alarm, mae_before_mm, mae_after_mm) VALUES (:run,"
          " :wheel, :channel, :wear, :clearance, :temp, :samples, :flagged, :alarm, :before,"
          " :after)",
      use(run_ids), use(wheel_ids), use(channels), use(wear.values, wear.present),
      use(clearance.values, clearance.present), use(temps), use(samples), use(flagged), use(alarms),
      use(mae_before.values, mae_before.present), use(mae_after.values, mae_after.present);
}

void SociStore::insert_alarm_events(long long run_id, const RunRecord& run, WheelIds& created) {
  if (run.alarms.empty()) return;
  std::vector<long long> run_ids, wheel_ids;
  std::vector<soci::indicator> has_wheel;
  std::vector<double> times;
  std::vector<std::string> what;
  for (const AlarmEventRecord& event : run.alarms) {
    const auto wheel = event_wheel(run, event.axle, event.side, created);
    run_ids.push_back(run_id);
    wheel_ids.push_back(wheel.value_or(0));
    has_wheel.push_back(wheel ? soci::i_ok : soci::i_null);
    times.push_back(event.t_s);
    what.push_back(event.what);
  }
  sql_ << "INSERT INTO alarm_events (run_id, wheel_id, t_s, what)"
          " VALUES (:run, :wheel, :t, :what)",
      use(run_ids), use(wheel_ids, has_wheel), use(times), use(what);
}

void SociStore::insert_trace(long long run_id, const RunRecord& run, WheelIds& created) {
  if (run.trace.empty()) return;
  std::vector<long long> run_ids, wheel_ids, samples;
  std::vector<soci::indicator> has_wheel;
  std::vector<double> km, clearance, temp;
  for (const TracePoint& point : run.trace) {
    const auto wheel = event_wheel(run, point.axle, point.side, created);
    run_ids.push_back(run_id);
    wheel_ids.push_back(wheel.value_or(0));
    has_wheel.push_back(wheel ? soci::i_ok : soci::i_null);
    km.push_back(point.km);
    clearance.push_back(point.clearance_mm);
    temp.push_back(point.temp_c);
    samples.push_back(static_cast<long long>(point.samples));
  }
  sql_ << "INSERT INTO run_trace (run_id, wheel_id, km, clearance_mm, temp_c, samples)"
          " VALUES (:run, :wheel, :km, :clearance, :temp, :samples)",
      use(run_ids), use(wheel_ids, has_wheel), use(km), use(clearance), use(temp), use(samples);
}

long long SociStore::insert_run_row(const RunRecord& run) {
  std::optional<long long> locomotive;
  if (!run.locomotive.empty()) locomotive = locomotive_id(run.locomotive);
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

long long SociStore::insert_run(const RunRecord& run, WheelIds& created) {
  const long long id = insert_run_row(run);
  insert_wheel_runs(id, run, created);
  insert_alarm_events(id, run, created);
  insert_trace(id, run, created);
  return id;
}

std::int64_t SociStore::record_run(const RunRecord& run) {
  return store_guarded(url_.shown, "recording a run", [&]() -> std::int64_t {
    WriteTransaction transaction(sql_, url_.backend);
    WheelIds created;
    const long long id = insert_run(run, created);
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
    for (const RunRecord& run : runs) ids.push_back(insert_run(run, created));
    pause_for_test();
    transaction.commit();
    wheel_ids_.insert(created.begin(), created.end());
    return ids;
  });
}

}  // namespace flange::host
