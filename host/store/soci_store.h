// SPDX-License-Identifier: MIT
// The Store over a SOCI session: the same SQL on SQLite and PostgreSQL (both speak
// INSERT ... ON CONFLICT and RETURNING); store_schema.cpp spells the few words they differ in.
#pragma once

#include <soci/soci.h>

#include <map>
#include <optional>
#include <string>
#include <tuple>

#include "store.h"
#include "store_url.h"

namespace flange::host {

class SociStore final : public Store {
 public:
  // Connects and migrates to `schema_version` (tests make older stores with it).
  SociStore(const StoreUrl& url, int schema_version);

  const std::string& name() const override { return url_.shown; }
  std::string backend() const override;
  int schema_version() const override { return schema_version_; }

  void upsert_locomotive(const LocomotiveRecord& locomotive) override;
  void upsert_wheel(const WheelRecord& wheel) override;
  void upsert_sensor(const SensorRecord& sensor) override;
  std::int64_t record_session(const SessionRecord& session,
                              const std::vector<BenchRow>& bench_rows) override;
  std::int64_t record_calibration(const CalibrationRecord& calibration) override;
  std::int64_t record_run(const RunRecord& run) override;
  std::int64_t record_maintenance(const MaintenanceRecord& event) override;
  std::vector<std::int64_t> record_runs(const std::vector<RunRecord>& runs) override;
  void write_wear_estimates(const WearEstimateSet& set) override;

  std::vector<LocomotiveRecord> locomotives() override;
  std::vector<StoredWheel> wheels() override;
  std::vector<WearPoint> wear_history(const WheelKey& wheel) override;
  std::vector<WheelSeries> wear_series() override;
  std::vector<FleetRow> fleet_table() override;
  std::vector<StoredMaintenance> maintenance_events(const std::string& locomotive) override;
  std::vector<StoredAlarmEvent> alarm_events(const std::string& locomotive) override;
  std::vector<std::pair<std::int64_t, SessionRecord>> sessions(SessionKind kind) override;
  std::vector<BenchRow> bench_rows(std::int64_t session_id) override;
  std::vector<std::pair<std::int64_t, CalibrationRecord>> calibrations() override;
  std::vector<TracePoint> run_trace(std::int64_t run_id) override;
  std::uint64_t run_count() override;
  StoreMarks marks() override;
  std::optional<WearEstimateSet> wear_estimates() override;
  std::uint64_t size_bytes() override;

 private:
  // Ids by (locomotive, axle, side); axle 0 with side "" is the locomotive's own id.
  using WheelIds = std::map<std::tuple<std::string, int, std::string>, long long>;

  // Get-or-create inside the caller's transaction; new ids go to `created` (cached on commit).
  long long locomotive_id(const std::string& name, WheelIds& created);
  long long wheel_id(const WheelKey& wheel, int channel, WheelIds& created);
  std::optional<long long> existing_wheel_id(const WheelKey& wheel);
  std::optional<long long> sensor_id(const std::string& serial);
  void insert_bench_rows(long long session_id, const std::vector<BenchRow>& rows);
  long long insert_session(const SessionRecord& session, const std::vector<BenchRow>& rows);
  struct RunBatches;
  long long insert_run_row(const RunRecord& run, WheelIds& created);
  long long insert_run(const RunRecord& run, WheelIds& created, RunBatches& batches);
  // The runs' own rows, their ids in order: one statement on PostgreSQL, one per run on SQLite.
  std::vector<long long> insert_run_rows(const std::vector<RunRecord>& runs, WheelIds& created);
  void add_wheel_runs(long long run_id, const RunRecord& run, WheelIds& created,
                      RunBatches& batches);
  void add_alarm_events(long long run_id, const RunRecord& run, WheelIds& created,
                        RunBatches& batches);
  void add_trace(long long run_id, const RunRecord& run, WheelIds& created, RunBatches& batches);
  std::optional<long long> event_wheel(const RunRecord& run, int axle, const std::string& side,
                                       WheelIds& created);

  StoreUrl url_;
  soci::session sql_;
  int schema_version_ = 0;
  WheelIds wheel_ids_;  // committed wheels and locomotives: ids never change once written
};

// One line: the store, what it was doing, the backend's message with its line breaks folded.
[[noreturn]] void throw_store_error(const std::string& store, const char* action,
                                    const std::string& what);

// Runs `body`, turning a SOCI error into one StoreError line naming the store and the action.
template <typename Body>
auto store_guarded(const std::string& store, const char* action, Body&& body) {
  try {
    return body();
  } catch (const soci::soci_error& error) {
    throw_store_error(store, action, error.what());
  }
}

}  // namespace flange::host
