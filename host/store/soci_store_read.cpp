// SPDX-License-Identifier: MIT
// The store's reads: wheels, a wheel's wear history, events, sessions, calibrations.
#include "soci_store.h"
#include "store_migration.h"

namespace flange::host {

namespace {

using soci::into;
using soci::use;

std::optional<double> optional_of(double value, soci::indicator indicator) {
  if (indicator == soci::i_ok) return value;
  return std::nullopt;
}

std::string text_or_empty(const std::string& value, soci::indicator indicator) {
  return indicator == soci::i_ok ? value : std::string();
}

}  // namespace

std::vector<LocomotiveRecord> SociStore::locomotives() {
  return store_guarded(url_.shown, "reading locomotives", [&] {
    std::vector<LocomotiveRecord> found;
    LocomotiveRecord row;
    soci::statement query =
        (sql_.prepare << "SELECT name, description FROM locomotives ORDER BY name", into(row.name),
         into(row.description));
    query.execute();
    while (query.fetch()) found.push_back(row);
    return found;
  });
}

std::vector<StoredWheel> SociStore::wheels() {
  return store_guarded(url_.shown, "reading wheels", [&] {
    std::vector<StoredWheel> found;
    StoredWheel row;
    soci::indicator has_sensor = soci::i_null;
    // The sensor fitted now: the wheel's latest fitment, if that is still the sensor's latest.
    soci::statement query =
        (sql_.prepare << "SELECT l.name, w.axle, w.side, w.channel, (SELECT s.serial"
                         " FROM sensor_fitments f JOIN sensors s ON s.id = f.sensor_id"
                         " WHERE f.wheel_id = w.id AND f.id = (SELECT f2.id FROM sensor_fitments"
                         " f2 WHERE f2.sensor_id = f.sensor_id ORDER BY f2.fitted_at DESC,"
                         " f2.id DESC LIMIT 1) ORDER BY f.fitted_at DESC, f.id DESC LIMIT 1)"
                         " FROM wheels w JOIN locomotives l ON l.id = w.locomotive_id"
                         " ORDER BY l.name, w.axle, w.side",
         into(row.wheel.wheel.locomotive), into(row.wheel.wheel.axle), into(row.wheel.wheel.side),
         into(row.wheel.channel), into(row.sensor_serial, has_sensor));
    query.execute();
    while (query.fetch()) {
      if (has_sensor != soci::i_ok) row.sensor_serial.clear();
      found.push_back(row);
    }
    return found;
  });
}

std::vector<WearPoint> SociStore::wear_history(const WheelKey& wheel) {
  return store_guarded(url_.shown, "reading a wheel's wear history", [&] {
    std::vector<WearPoint> found;
    const auto wheel_row = existing_wheel_id(wheel);
    if (!wheel_row) return found;
    const long long wheel_value = *wheel_row;
    WearPoint point;
    long long run_id = 0, samples = 0;
    double wear = 0.0, clearance = 0.0;
    soci::indicator has_wear = soci::i_null, has_clearance = soci::i_null,
                    has_sensor = soci::i_null;
    soci::statement query =
        (sql_.prepare << "SELECT w.run_id, w.started_at, w.odometer_km, w.wear_mm, w.clearance_mm,"
                         " w.temp_c, w.samples, w.final_alarm, (SELECT s.serial FROM"
                         " sensor_fitments f JOIN sensors s ON s.id = f.sensor_id"
                         " WHERE f.wheel_id = w.wheel_id AND f.fitted_at <= w.started_at"
                         " ORDER BY f.fitted_at DESC, f.id DESC LIMIT 1)"
                         " FROM wheel_runs w WHERE w.wheel_id = :wheel"
                         " ORDER BY w.started_at, w.run_id",
         use(wheel_value), into(run_id), into(point.started_at), into(point.odometer_km),
         into(wear, has_wear), into(clearance, has_clearance), into(point.temp_c), into(samples),
         into(point.final_alarm), into(point.sensor_serial, has_sensor));
    query.execute();
    while (query.fetch()) {
      point.run_id = run_id;
      point.wear_mm = optional_of(wear, has_wear);
      point.clearance_mm = optional_of(clearance, has_clearance);
      point.samples = static_cast<std::uint64_t>(samples);
      if (has_sensor != soci::i_ok) point.sensor_serial.clear();
      found.push_back(point);
    }
    return found;
  });
}

std::vector<StoredMaintenance> SociStore::maintenance_events(const std::string& locomotive) {
  return store_guarded(url_.shown, "reading maintenance events", [&] {
    std::vector<StoredMaintenance> found;
    StoredMaintenance row;
    long long id = 0;
    int from_axle = 0;
    soci::indicator has_from_axle = soci::i_null;
    const int all = locomotive.empty() ? 1 : 0;
    // A store older than kFromAxleSchemaVersion has no source axles (its notes hold them).
    const std::string from_axle_column =
        schema_version_ >= kFromAxleSchemaVersion ? "m.from_axle" : "NULL";
    soci::statement query =
        (sql_.prepare << "SELECT m.id, l.name, w.axle, w.side, m.at, m.odometer_km, m.kind,"
                         " m.note, " +
                             from_axle_column +
                             " FROM maintenance_events m JOIN wheels w ON w.id = m.wheel_id"
                             " JOIN locomotives l ON l.id = w.locomotive_id"
                             " WHERE :all = 1 OR l.name = :name ORDER BY m.at, m.id",
         use(all, "all"), use(locomotive, "name"), into(id), into(row.event.wheel.locomotive),
         into(row.event.wheel.axle), into(row.event.wheel.side), into(row.event.at),
         into(row.event.odometer_km), into(row.event.kind), into(row.event.note),
         into(from_axle, has_from_axle));
    query.execute();
    while (query.fetch()) {
      row.id = id;
      row.event.from_axle =
          has_from_axle == soci::i_ok ? std::optional<int>(from_axle) : std::nullopt;
      found.push_back(row);
    }
    return found;
  });
}

std::vector<StoredAlarmEvent> SociStore::alarm_events(const std::string& locomotive) {
  return store_guarded(url_.shown, "reading alarm events", [&] {
    std::vector<StoredAlarmEvent> found;
    StoredAlarmEvent row;
    long long run_id = 0;
    int axle = 0;
    const int all = locomotive.empty() ? 1 : 0;
    std::string name, side;
    soci::indicator has_wheel = soci::i_null, has_side = soci::i_null, has_name = soci::i_null;
    soci::statement query =
        (sql_.prepare << "SELECT e.run_id, r.started_at, l.name, w.axle, w.side, e.t_s, e.what"
                         " FROM alarm_events e JOIN runs r ON r.id = e.run_id"
                         " LEFT JOIN wheels w ON w.id = e.wheel_id"
                         " LEFT JOIN locomotives l ON l.id = r.locomotive_id"
                         " WHERE :all = 1 OR l.name = :name ORDER BY r.started_at, e.run_id,"
                         " e.t_s, e.id",
         use(all, "all"), use(locomotive, "name"), into(run_id), into(row.run_started_at),
         into(name, has_name), into(axle, has_wheel), into(side, has_side), into(row.t_s),
         into(row.what));
    query.execute();
    while (query.fetch()) {
      row.run_id = run_id;
      row.wheel.reset();
      if (has_wheel == soci::i_ok) row.wheel = WheelKey{text_or_empty(name, has_name), axle, side};
      found.push_back(row);
    }
    return found;
  });
}

std::vector<TracePoint> SociStore::run_trace(std::int64_t run_id) {
  return store_guarded(url_.shown, "reading a run's trace", [&] {
    std::vector<TracePoint> found;
    const auto run_value = static_cast<long long>(run_id);
    TracePoint point;
    long long samples = 0;
    int axle = 0;
    std::string side;
    soci::indicator has_axle = soci::i_null, has_side = soci::i_null;
    soci::statement query =
        (sql_.prepare << "SELECT w.axle, w.side, t.km, t.clearance_mm, t.temp_c, t.samples"
                         " FROM run_trace t LEFT JOIN wheels w ON w.id = t.wheel_id"
                         " WHERE t.run_id = :run ORDER BY w.axle, w.side, t.km",
         use(run_value), into(axle, has_axle), into(side, has_side), into(point.km),
         into(point.clearance_mm), into(point.temp_c), into(samples));
    query.execute();
    while (query.fetch()) {
      point.axle = has_axle == soci::i_ok ? axle : 0;
      point.side = text_or_empty(side, has_side);
      point.samples = static_cast<std::uint64_t>(samples);
      found.push_back(point);
    }
    return found;
  });
}

std::uint64_t SociStore::run_count() {
  return store_guarded(url_.shown, "counting runs", [&] {
    long long count = 0;
    sql_ << "SELECT COUNT(*) FROM runs", into(count);
    return static_cast<std::uint64_t>(count);
  });
}

std::uint64_t SociStore::size_bytes() {
  return store_guarded(url_.shown, "measuring the store", [&] {
    long long bytes = 0;
    if (url_.backend == StoreBackend::kSqlite) {
      long long pages = 0, page_size = 0;
      sql_ << "PRAGMA page_count", into(pages);
      sql_ << "PRAGMA page_size", into(page_size);
      bytes = pages * page_size;
    } else {
      sql_ << "SELECT pg_database_size(current_database())", into(bytes);
    }
    return static_cast<std::uint64_t>(bytes);
  });
}

}  // namespace flange::host
