// SPDX-License-Identifier: MIT
// The measurement store: one interface over SQLite (one file, no server) and PostgreSQL (a
// server shared by many writers), chosen by URL (store_url.h). docs/store.md has the schema.
//
// What each call guarantees:
//  - open_store creates the schema in an empty store or migrates an older one, in one
//    transaction; a store written by a newer flange is refused (StoreError, nothing changed).
//  - Every write call is ONE transaction: it is written whole or not at all. A process killed
//    in the middle, a lost connection or an error leaves the store as it was before the call.
//    record_run writes the run, its per-wheel results, alarm events and reduced trace together.
//  - Writers may run at once (several processes, each with its own Store): SQLite runs in WAL
//    mode and waits up to the busy timeout for the write lock; PostgreSQL serialises through
//    its own transactions. Nothing committed is lost.
//  - Upserts are idempotent: the same locomotive, wheel or sensor written twice is one row
//    (changed fields updated; a sensor fitted to another wheel adds a fitment, the old kept).
//  - All values reach SQL as bound parameters, never spliced into the statement text.
//  - Reads see the committed state at the time of the call.
// Errors: StoreUrlError for a malformed URL (a bad argument: exit status 2), StoreError for
// everything the store cannot do (unreachable server, wrong credentials, read-only file, newer
// schema, a constraint violated): exit status 1. Both carry one line naming the store.
// A Store object is used from one thread at a time.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "store_records.h"

namespace flange::host {

// The store cannot do what was asked (runtime failure, exit status 1).
class StoreError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The store URL is malformed (bad argument, exit status 2).
class StoreUrlError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

class Store {
 public:
  virtual ~Store() = default;

  // The URL as given, with any password masked: for messages.
  virtual const std::string& name() const = 0;
  // "sqlite" or "postgresql".
  virtual std::string backend() const = 0;
  virtual int schema_version() const = 0;

  // ---- writes (each one transaction) ----
  virtual void upsert_locomotive(const LocomotiveRecord& locomotive) = 0;
  // Creates the locomotive when it is new; sets the channel of a wheel already stored.
  virtual void upsert_wheel(const WheelRecord& wheel) = 0;
  // Creates the wheel (channel from the wheel's axle and side) when it is new.
  virtual void upsert_sensor(const SensorRecord& sensor) = 0;
  // A bench session with all its rows, or a service session (rows empty). Returns its id.
  // A session of the same kind, label and source hash already stored is returned, not repeated.
  virtual std::int64_t record_session(const SessionRecord& session,
                                      const std::vector<BenchRow>& bench_rows) = 0;
  virtual std::int64_t record_calibration(const CalibrationRecord& calibration) = 0;
  // The run with its wheels, alarm events and reduced trace; creates the locomotive and its
  // wheels when they are new. Returns the run's id. (A wheel, locomotive or sensor that any
  // write names is created when new; a wheel created so takes default_channel.)
  virtual std::int64_t record_run(const RunRecord& run) = 0;
  virtual std::int64_t record_maintenance(const MaintenanceRecord& event) = 0;
  // Many runs in ONE transaction (a day's fleet, an import): all written or none. Their ids in
  // order. Faster than one record_run each where every commit waits for the disk.
  virtual std::vector<std::int64_t> record_runs(const std::vector<RunRecord>& runs) = 0;
  // Replaces the stored wear estimates by `set` (one transaction).
  virtual void write_wear_estimates(const WearEstimateSet& set) = 0;

  // ---- reads ----
  virtual std::vector<LocomotiveRecord> locomotives() = 0;
  // Every wheel, by locomotive, axle, side.
  virtual std::vector<StoredWheel> wheels() = 0;
  // One wheel's runs in time order. Empty for a wheel with no runs (or none stored).
  virtual std::vector<WearPoint> wear_history(const WheelKey& wheel) = 0;
  // Every wheel's runs (the wear estimate's columns), by locomotive, axle, side, each in time
  // order: a few queries in all, not one per wheel (a national fleet's store holds millions).
  virtual std::vector<WheelSeries> wear_series() = 0;
  // Every wheel's summary in one query, by locomotive, axle, side.
  virtual std::vector<FleetRow> fleet_table() = 0;
  // Maintenance events of one locomotive ("" for all), in time order.
  virtual std::vector<StoredMaintenance> maintenance_events(const std::string& locomotive) = 0;
  // Alarm events of one locomotive ("" for all), by run time then t_s.
  virtual std::vector<StoredAlarmEvent> alarm_events(const std::string& locomotive) = 0;
  // Sessions of one kind, in id order: (id, record).
  virtual std::vector<std::pair<std::int64_t, SessionRecord>> sessions(SessionKind kind) = 0;
  // The rows of one bench session, in the order recorded.
  virtual std::vector<BenchRow> bench_rows(std::int64_t session_id) = 0;
  virtual std::vector<std::pair<std::int64_t, CalibrationRecord>> calibrations() = 0;
  // The reduced trace of one run.
  virtual std::vector<TracePoint> run_trace(std::int64_t run_id) = 0;
  virtual std::uint64_t run_count() = 0;
  // The latest run, maintenance event and calibration ids (0 for none).
  virtual StoreMarks marks() = 0;
  // The wear estimates last written (none before the first), wheels by locomotive, axle, side.
  virtual std::optional<WearEstimateSet> wear_estimates() = 0;
  // The store's size on disk in bytes (SQLite: the file's pages; PostgreSQL: the database).
  virtual std::uint64_t size_bytes() = 0;
};

// Opens (creating or migrating) the store at `url`: "sqlite:PATH" or "postgresql://...".
// Throws StoreUrlError for a malformed URL, StoreError when it cannot be opened.
std::unique_ptr<Store> open_store(const std::string& url);

}  // namespace flange::host
