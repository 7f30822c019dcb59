// SPDX-License-Identifier: MIT
// The store's writes: each one transaction, every value a bound parameter.
#include "soci_store.h"
#include "store_migration.h"
#include "store_transaction.h"
#include "wheel_fit_table.h"

namespace flange::host {

namespace {

using soci::into;
using soci::use;

soci::indicator present(const std::optional<double>& value) {
  return value ? soci::i_ok : soci::i_null;
}

// The note a store older than kFromAxleSchemaVersion holds: the source axle written in front of
// the depot's words, as the flange of that schema wrote it (migration 5 reads it back).
std::string older_schema_note(const MaintenanceRecord& event) {
  if (!event.from_axle) return event.note;
  return "from axle " + std::to_string(*event.from_axle) +
         (event.note.empty() ? "" : "; " + event.note);
}

void into_cache(std::map<std::tuple<std::string, int, std::string>, long long>& cache,
                const std::map<std::tuple<std::string, int, std::string>, long long>& created) {
  cache.insert(created.begin(), created.end());
}

}  // namespace

long long SociStore::locomotive_id(const std::string& name, WheelIds& created) {
  const auto key = std::make_tuple(name, 0, std::string());
  if (const auto cached = wheel_ids_.find(key); cached != wheel_ids_.end()) return cached->second;
  if (const auto known = created.find(key); known != created.end()) return known->second;
  sql_ << "INSERT INTO locomotives (name) VALUES (:name) ON CONFLICT (name) DO NOTHING", use(name);
  long long id = 0;
  sql_ << "SELECT id FROM locomotives WHERE name = :name", use(name), into(id);
  created[key] = id;  // cached once committed
  return id;
}

std::optional<long long> SociStore::existing_wheel_id(const WheelKey& wheel) {
  const auto key = std::make_tuple(wheel.locomotive, wheel.axle, wheel.side);
  if (const auto cached = wheel_ids_.find(key); cached != wheel_ids_.end()) return cached->second;
  long long id = 0;
  soci::indicator found = soci::i_null;
  sql_ << "SELECT w.id FROM wheels w JOIN locomotives l ON l.id = w.locomotive_id"
          " WHERE l.name = :name AND w.axle = :axle AND w.side = :side",
      use(wheel.locomotive), use(wheel.axle), use(wheel.side), into(id, found);
  if (!sql_.got_data() || found != soci::i_ok) return std::nullopt;
  wheel_ids_[key] = id;  // committed by another transaction: stable
  return id;
}

long long SociStore::wheel_id(const WheelKey& wheel, int channel, WheelIds& created) {
  const auto key = std::make_tuple(wheel.locomotive, wheel.axle, wheel.side);
  if (const auto known = created.find(key); known != created.end()) return known->second;
  if (const auto existing = existing_wheel_id(wheel)) return *existing;
  const long long locomotive = locomotive_id(wheel.locomotive, created);
  sql_ << "INSERT INTO wheels (locomotive_id, axle, side, channel)"
          " VALUES (:locomotive, :axle, :side, :channel)"
          " ON CONFLICT (locomotive_id, axle, side) DO NOTHING",
      use(locomotive), use(wheel.axle), use(wheel.side), use(channel);
  long long id = 0;
  sql_ << "SELECT id FROM wheels WHERE locomotive_id = :locomotive AND axle = :axle"
          " AND side = :side",
      use(locomotive), use(wheel.axle), use(wheel.side), into(id);
  created[key] = id;
  return id;
}

std::optional<long long> SociStore::sensor_id(const std::string& serial) {
  long long id = 0;
  soci::indicator found = soci::i_null;
  sql_ << "SELECT id FROM sensors WHERE serial = :serial", use(serial), into(id, found);
  if (!sql_.got_data() || found != soci::i_ok) return std::nullopt;
  return id;
}

void SociStore::upsert_locomotive(const LocomotiveRecord& locomotive) {
  store_guarded(url_.shown, "writing a locomotive", [&] {
    WriteTransaction transaction(sql_, url_.backend);
    sql_ << "INSERT INTO locomotives (name, description) VALUES (:name, :description)"
            " ON CONFLICT (name) DO UPDATE SET description = excluded.description",
        use(locomotive.name), use(locomotive.description);
    transaction.commit();
  });
}

void SociStore::upsert_wheel(const WheelRecord& wheel) {
  store_guarded(url_.shown, "writing a wheel", [&] {
    WriteTransaction transaction(sql_, url_.backend);
    WheelIds created;
    const long long id = wheel_id(wheel.wheel, wheel.channel, created);
    sql_ << "UPDATE wheels SET channel = :channel WHERE id = :id", use(wheel.channel), use(id);
    transaction.commit();
    into_cache(wheel_ids_, created);
  });
}

void SociStore::upsert_sensor(const SensorRecord& sensor) {
  store_guarded(url_.shown, "writing a sensor", [&] {
    WriteTransaction transaction(sql_, url_.backend);
    sql_ << "INSERT INTO sensors (serial, model) VALUES (:serial, :model) ON CONFLICT (serial)"
            " DO UPDATE SET model = CASE WHEN excluded.model = '' THEN sensors.model"
            " ELSE excluded.model END",
        use(sensor.serial), use(sensor.model);
    WheelIds created;
    if (sensor.fitted_to) {
      const long long sensor_row = *sensor_id(sensor.serial);
      const long long wheel =
          wheel_id(*sensor.fitted_to, default_channel(*sensor.fitted_to), created);
      long long fitted_wheel = -1;
      soci::indicator found = soci::i_null;
      sql_ << "SELECT wheel_id FROM sensor_fitments WHERE sensor_id = :sensor"
              " ORDER BY fitted_at DESC, id DESC LIMIT 1",
          use(sensor_row), into(fitted_wheel, found);
      if (!sql_.got_data() || found != soci::i_ok || fitted_wheel != wheel) {
        sql_ << "INSERT INTO sensor_fitments (sensor_id, wheel_id, fitted_at)"
                " VALUES (:sensor, :wheel, :at)",
            use(sensor_row), use(wheel), use(sensor.fitted_at);
      }
    }
    transaction.commit();
    into_cache(wheel_ids_, created);
  });
}

long long SociStore::insert_session(const SessionRecord& session,
                                    const std::vector<BenchRow>& bench_rows) {
  const std::string kind = session_kind_name(session.kind);
  long long id = 0;
  soci::indicator found = soci::i_null;
  sql_ << "SELECT id FROM sessions WHERE kind = :kind AND label = :label"
          " AND source_sha256 = :sha",
      use(kind), use(session.label), use(session.source_sha256), into(id, found);
  if (sql_.got_data() && found == soci::i_ok) return id;  // stored already
  std::optional<long long> sensor;
  if (!session.sensor_serial.empty()) {
    sql_ << "INSERT INTO sensors (serial) VALUES (:serial) ON CONFLICT (serial) DO NOTHING",
        use(session.sensor_serial);
    sensor = sensor_id(session.sensor_serial);
  }
  long long sensor_value = sensor.value_or(0);
  soci::indicator sensor_indicator = sensor ? soci::i_ok : soci::i_null;
  sql_ << "INSERT INTO sessions (kind, label, started_at, sample_rate_hz, source_file,"
          " source_sha256, sensor_id) VALUES (:kind, :label, :at, :fs, :file, :sha, :sensor)"
          " RETURNING id",
      use(kind), use(session.label), use(session.started_at), use(session.sample_rate_hz),
      use(session.source_file), use(session.source_sha256), use(sensor_value, sensor_indicator),
      into(id);
  if (!bench_rows.empty()) insert_bench_rows(id, bench_rows);
  return id;
}

std::int64_t SociStore::record_session(const SessionRecord& session,
                                       const std::vector<BenchRow>& bench_rows) {
  return store_guarded(url_.shown, "recording a session", [&]() -> std::int64_t {
    WriteTransaction transaction(sql_, url_.backend);
    const long long id = insert_session(session, bench_rows);
    transaction.commit();
    return id;
  });
}

void SociStore::insert_bench_rows(long long id, const std::vector<BenchRow>& bench_rows) {
  std::vector<long long> session_ids(bench_rows.size(), id), seq(bench_rows.size());
  std::vector<double> t(bench_rows.size()), clearance(bench_rows.size()), temp(bench_rows.size()),
      voltage(bench_rows.size());
  std::vector<soci::indicator> has_clearance(bench_rows.size());
  for (std::size_t i = 0; i < bench_rows.size(); ++i) {
    seq[i] = static_cast<long long>(i);
    t[i] = bench_rows[i].t_s;
    clearance[i] = bench_rows[i].clearance_mm.value_or(0.0);
    has_clearance[i] = present(bench_rows[i].clearance_mm);
    temp[i] = bench_rows[i].temp_c;
    voltage[i] = bench_rows[i].voltage_v;
  }
  sql_ << "INSERT INTO bench_rows (session_id, seq, t_s, clearance_mm, temp_c, voltage_v)"
          " VALUES (:session, :seq, :t, :clearance, :temp, :voltage)",
      use(session_ids), use(seq), use(t), use(clearance, has_clearance), use(temp), use(voltage);
}

std::int64_t SociStore::record_calibration(const CalibrationRecord& calibration) {
  return store_guarded(url_.shown, "recording a calibration", [&]() -> std::int64_t {
    WriteTransaction transaction(sql_, url_.backend);
    std::optional<long long> sensor;
    if (!calibration.sensor_serial.empty()) {
      sql_ << "INSERT INTO sensors (serial) VALUES (:serial) ON CONFLICT (serial) DO NOTHING",
          use(calibration.sensor_serial);
      sensor = sensor_id(calibration.sensor_serial);
    }
    long long sensor_value = sensor.value_or(0);
    soci::indicator sensor_indicator = sensor ? soci::i_ok : soci::i_null;
    const auto rows = static_cast<long long>(calibration.rows);
    long long id = 0;
    sql_ << "INSERT INTO calibrations (fitted_at, sensor_id, model_json, fitted_rows, rmse_mm)"
            " VALUES (:at, :sensor, :model, :rows, :rmse) RETURNING id",
        use(calibration.fitted_at), use(sensor_value, sensor_indicator),
        use(calibration.model_json), use(rows), use(calibration.rmse_mm), into(id);
    for (const std::int64_t session : calibration.session_ids) {
      const auto session_id = static_cast<long long>(session);
      sql_ << "INSERT INTO calibration_sessions (calibration_id, session_id)"
              " VALUES (:calibration, :session)",
          use(id), use(session_id);
    }
    transaction.commit();
    return id;
  });
}

std::int64_t SociStore::record_maintenance(const MaintenanceRecord& event) {
  return store_guarded(url_.shown, "recording a maintenance event", [&]() -> std::int64_t {
    WriteTransaction transaction(sql_, url_.backend);
    WheelIds created;
    const long long wheel = wheel_id(event.wheel, default_channel(event.wheel), created);
    long long id = 0;
    if (schema_version_ >= kFromAxleSchemaVersion) {
      int from_axle = event.from_axle.value_or(0);
      soci::indicator has_from_axle = event.from_axle ? soci::i_ok : soci::i_null;
      sql_ << "INSERT INTO maintenance_events (wheel_id, at, odometer_km, kind, note, from_axle)"
              " VALUES (:wheel, :at, :km, :kind, :note, :from_axle) RETURNING id",
          use(wheel), use(event.at), use(event.odometer_km), use(event.kind), use(event.note),
          use(from_axle, has_from_axle), into(id);
    } else {
      const std::string note = older_schema_note(event);
      sql_ << "INSERT INTO maintenance_events (wheel_id, at, odometer_km, kind, note)"
              " VALUES (:wheel, :at, :km, :kind, :note) RETURNING id",
          use(wheel), use(event.at), use(event.odometer_km), use(event.kind), use(note), into(id);
    }
    if (schema_version_ >= kWheelFitSchemaVersion) refit_wheel_since_maintenance(sql_, wheel);
    transaction.commit();
    into_cache(wheel_ids_, created);
    return id;
  });
}

}  // namespace flange::host
