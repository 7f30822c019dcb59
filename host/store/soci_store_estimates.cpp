// SPDX-License-Identifier: MIT
// The wear estimates `flange wear` keeps (schema version 4: wear_estimates, one row: when and
// with which settings; wheel_estimates, one row per wheel; version 6 adds its sensor flag, 7 the
// forecast's bend), and the store's marks that say
// whether they are current. Written whole in one transaction; read in two queries.
#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <map>

#include "column_batch.h"
#include "soci_store.h"
#include "store_migration.h"
#include "store_transaction.h"

namespace flange::host {

namespace {

using soci::into;
using soci::use;

// wheel_estimates' columns after wheel_id, as written and read, with their PostgreSQL types.
const std::vector<std::pair<std::string, std::string>>& estimate_columns() {
  static const std::vector<std::pair<std::string, std::string>> columns = {
      {"wheel_id", "BIGINT"},
      {"status", "TEXT"},
      {"has_fit", "INTEGER"},
      {"segment_start", "TEXT"},
      {"last_run_at", "TEXT"},
      {"last_run_day", "DOUBLE PRECISION"},
      {"rate", "DOUBLE PRECISION"},
      {"rate_low", "DOUBLE PRECISION"},
      {"rate_high", "DOUBLE PRECISION"},
      {"rate_se", "DOUBLE PRECISION"},
      {"rate_dof", "INTEGER"},
      {"fit_dof", "INTEGER"},
      {"clearance_now_mm", "DOUBLE PRECISION"},
      {"wear_now_mm", "DOUBLE PRECISION"},
      {"km_per_day", "DOUBLE PRECISION"},
      {"km_per_day_se", "DOUBLE PRECISION"},
      {"day_km_sd", "DOUBLE PRECISION"},
      {"km_per_day_dof", "INTEGER"},
      {"clearance_now_se_mm", "DOUBLE PRECISION"},
      {"clearance_rate_covariance", "DOUBLE PRECISION"},
      {"critical_reached", "INTEGER"},
      {"critical_date", "TEXT"},
      {"warning_date", "TEXT"}};
  return columns;
}

// ... and the sensor flag's, from schema version 6 on.
const std::vector<std::pair<std::string, std::string>>& flag_columns() {
  static const std::vector<std::pair<std::string, std::string>> columns = {
      {"sensor_flag_first", "TEXT"}, {"sensor_flag_confirmed", "TEXT"}};
  return columns;
}

// ... and the dates' forecast input, from schema version 7 on.
const std::vector<std::pair<std::string, std::string>>& forecast_columns() {
  static const std::vector<std::pair<std::string, std::string>> columns = {
      {"forecast", "TEXT"}};
  return columns;
}

void add_row(ColumnBatch& rows, long long wheel_id, const WheelEstimateRecord& e, bool with_flags,
             bool with_forecast) {
  rows.add(wheel_id);
  rows.add(e.status);
  rows.add(static_cast<long long>(e.has_fit));
  rows.add(e.segment_start);
  rows.add(e.last_run_at);
  for (const double value :
       {e.last_run_day, e.rate_mm_per_1000km, e.rate_low, e.rate_high, e.rate_se}) {
    rows.add(value);  // a non-finite number is stored as NULL and read back as NaN
  }
  rows.add(static_cast<long long>(e.rate_dof));
  rows.add(static_cast<long long>(e.fit_dof));
  for (const double value :
       {e.clearance_now_mm, e.wear_now_mm, e.km_per_day, e.km_per_day_se, e.day_km_sd}) {
    rows.add(value);
  }
  rows.add(static_cast<long long>(e.km_per_day_dof));
  rows.add(e.clearance_now_se_mm);
  rows.add(e.clearance_rate_covariance);
  rows.add(static_cast<long long>(e.critical_reached));
  rows.add(e.critical_date);
  rows.add(e.warning_date);
  if (with_flags) {
    rows.add(e.sensor_flag_first);
    rows.add(e.sensor_flag_confirmed);
  }
  if (with_forecast) rows.add(e.forecast);
}

// A nullable REAL read into a double: NaN for NULL.
struct Real {
  double value = 0.0;
  soci::indicator present = soci::i_null;
  double get() const {
    return present == soci::i_ok ? value : std::numeric_limits<double>::quiet_NaN();
  }
};

// Every wheel's row, by locomotive, axle, side.
void read_wheel_estimates(soci::session& sql, std::vector<WheelEstimateRecord>& wheels,
                          bool with_flags, bool with_forecast) {
  WheelEstimateRecord e;
  int has_fit = 0, reached = 0;
  Real day, rate, low, high, se, clearance, wear, km, km_se, day_sd, clearance_se, covariance;
  soci::statement query =
      (sql.prepare << "SELECT l.name, w.axle, w.side, w.channel, e.status, e.has_fit,"
                      " e.segment_start, e.last_run_at, e.last_run_day, e.rate, e.rate_low,"
                      " e.rate_high, e.rate_se, e.rate_dof, e.fit_dof, e.clearance_now_mm,"
                      " e.wear_now_mm, e.km_per_day, e.km_per_day_se, e.day_km_sd,"
                      " e.km_per_day_dof, e.clearance_now_se_mm, e.clearance_rate_covariance,"
                      " e.critical_reached, e.critical_date, e.warning_date, " +
                          std::string(with_flags ? "e.sensor_flag_first, e.sensor_flag_confirmed"
                                                 : "'', ''") +
                          (with_forecast ? ", e.forecast" : ", ''") +
                          " FROM wheel_estimates e JOIN wheels w ON w.id = e.wheel_id"
                          " JOIN locomotives l ON l.id = w.locomotive_id"
                          " ORDER BY l.name, w.axle, w.side",
       into(e.wheel.locomotive), into(e.wheel.axle), into(e.wheel.side), into(e.channel),
       into(e.status), into(has_fit), into(e.segment_start), into(e.last_run_at),
       into(day.value, day.present), into(rate.value, rate.present), into(low.value, low.present),
       into(high.value, high.present), into(se.value, se.present), into(e.rate_dof),
       into(e.fit_dof), into(clearance.value, clearance.present), into(wear.value, wear.present),
       into(km.value, km.present), into(km_se.value, km_se.present),
       into(day_sd.value, day_sd.present), into(e.km_per_day_dof),
       into(clearance_se.value, clearance_se.present), into(covariance.value, covariance.present),
       into(reached), into(e.critical_date), into(e.warning_date), into(e.sensor_flag_first),
       into(e.sensor_flag_confirmed), into(e.forecast));
  query.execute();
  while (query.fetch()) {
    e.has_fit = has_fit != 0;
    e.critical_reached = reached != 0;
    e.last_run_day = day.get();
    e.rate_mm_per_1000km = rate.get();
    e.rate_low = low.get();
    e.rate_high = high.get();
    e.rate_se = se.get();
    e.clearance_now_mm = clearance.get();
    e.wear_now_mm = wear.get();
    e.km_per_day = km.get();
    e.km_per_day_se = km_se.get();
    e.day_km_sd = day_sd.get();
    e.clearance_now_se_mm = clearance_se.get();
    e.clearance_rate_covariance = covariance.get();
    wheels.push_back(e);
  }
}

}  // namespace

void SociStore::write_wear_estimates(const WearEstimateSet& set) {
  store_guarded(url_.shown, "writing the wear estimates", [&] {
    WriteTransaction transaction(sql_, url_.backend);
    std::map<std::tuple<std::string, int, std::string>, long long> ids;
    {
      std::string name, side;
      int axle = 0;
      long long id = 0;
      soci::statement wheels = (sql_.prepare << "SELECT l.name, w.axle, w.side, w.id FROM wheels w"
                                                " JOIN locomotives l ON l.id = w.locomotive_id",
                                into(name), into(axle), into(side), into(id));
      wheels.execute();
      while (wheels.fetch()) ids[{name, axle, side}] = id;
    }
    sql_ << "DELETE FROM wheel_estimates";
    sql_ << "DELETE FROM wear_estimates";
    long long run = set.marks.last_run_id, maintenance = set.marks.last_maintenance_id,
              calibration = set.marks.last_calibration_id;
    sql_ << "INSERT INTO wear_estimates (made_at, last_run_id, last_maintenance_id,"
            " last_calibration_id, warning_clearance_mm, critical_clearance_mm, max_step_mm)"
            " VALUES (:at, :run, :maintenance, :calibration, :warning, :critical, :step)",
        use(set.made_at), use(run), use(maintenance), use(calibration),
        use(set.warning_clearance_mm), use(set.critical_clearance_mm), use(set.max_step_mm);
    const bool with_flags = schema_version_ >= kSensorFlagSchemaVersion;
    auto columns = estimate_columns();
    const bool with_forecast = schema_version_ >= kForecastSchemaVersion;
    if (with_flags) columns.insert(columns.end(), flag_columns().begin(), flag_columns().end());
    if (with_forecast) columns.insert(columns.end(), forecast_columns().begin(), forecast_columns().end());
    ColumnBatch rows("wheel_estimates", columns);
    for (const WheelEstimateRecord& wheel : set.wheels) {
      const auto id = ids.find({wheel.wheel.locomotive, wheel.wheel.axle, wheel.wheel.side});
      if (id == ids.end()) {
        throw StoreError(fmt::format("store {}: writing the wear estimates: no wheel {} axle {} {}",
                                     url_.shown, wheel.wheel.locomotive, wheel.wheel.axle,
                                     wheel.wheel.side));
      }
      add_row(rows, id->second, wheel, with_flags, with_forecast);
    }
    rows.flush(sql_, url_.backend);
    transaction.commit();
  });
}

StoreMarks SociStore::marks() {
  return store_guarded(url_.shown, "reading the latest ids", [&] {
    long long run = 0, maintenance = 0, calibration = 0;
    sql_ << "SELECT COALESCE((SELECT MAX(id) FROM runs), 0),"
            " COALESCE((SELECT MAX(id) FROM maintenance_events), 0),"
            " COALESCE((SELECT MAX(id) FROM calibrations), 0)",
        into(run), into(maintenance), into(calibration);
    return StoreMarks{run, maintenance, calibration};
  });
}

std::optional<WearEstimateSet> SociStore::wear_estimates() {
  return store_guarded(url_.shown, "reading the wear estimates", [&] {
    std::optional<WearEstimateSet> found;
    if (schema_version_ < 4) return found;
    WearEstimateSet set;
    long long run = 0, maintenance = 0, calibration = 0;
    sql_ << "SELECT made_at, last_run_id, last_maintenance_id, last_calibration_id,"
            " warning_clearance_mm, critical_clearance_mm, max_step_mm FROM wear_estimates",
        into(set.made_at), into(run), into(maintenance), into(calibration),
        into(set.warning_clearance_mm), into(set.critical_clearance_mm), into(set.max_step_mm);
    if (!sql_.got_data()) return found;
    set.marks = {run, maintenance, calibration};
    read_wheel_estimates(sql_, set.wheels, schema_version_ >= kSensorFlagSchemaVersion,
                         schema_version_ >= kForecastSchemaVersion);
    found = std::move(set);
    return found;
  });
}

}  // namespace flange::host
