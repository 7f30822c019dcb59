// SPDX-License-Identifier: MIT
// Reading the bench side back: sessions, a bench session's rows, calibrations.
#include "soci_store.h"

namespace flange::host {

namespace {

using soci::into;
using soci::use;

}  // namespace

std::vector<std::pair<std::int64_t, SessionRecord>> SociStore::sessions(SessionKind kind) {
  return store_guarded(url_.shown, "reading sessions", [&] {
    std::vector<std::pair<std::int64_t, SessionRecord>> found;
    const std::string kind_name = session_kind_name(kind);
    SessionRecord row;
    row.kind = kind;
    long long id = 0;
    soci::indicator has_sensor = soci::i_null;
    soci::statement query =
        (sql_.prepare << "SELECT e.id, e.label, e.started_at, e.sample_rate_hz, e.source_file,"
                         " e.source_sha256, s.serial FROM sessions e"
                         " LEFT JOIN sensors s ON s.id = e.sensor_id WHERE e.kind = :kind"
                         " ORDER BY e.id",
         use(kind_name), into(id), into(row.label), into(row.started_at), into(row.sample_rate_hz),
         into(row.source_file), into(row.source_sha256), into(row.sensor_serial, has_sensor));
    query.execute();
    while (query.fetch()) {
      if (has_sensor != soci::i_ok) row.sensor_serial.clear();
      found.emplace_back(id, row);
    }
    return found;
  });
}

std::vector<BenchRow> SociStore::bench_rows(std::int64_t session_id) {
  return store_guarded(url_.shown, "reading bench rows", [&] {
    const auto session_value = static_cast<long long>(session_id);
    long long count = 0;
    sql_ << "SELECT COUNT(*) FROM bench_rows WHERE session_id = :session", use(session_value),
        into(count);
    std::vector<BenchRow> found;
    if (count == 0) return found;
    // One bulk fetch into columns.
    const auto n = static_cast<std::size_t>(count);
    std::vector<double> t(n), clearance(n), temp(n), voltage(n);
    std::vector<soci::indicator> has_clearance(n);
    sql_ << "SELECT t_s, clearance_mm, temp_c, voltage_v FROM bench_rows"
            " WHERE session_id = :session ORDER BY seq",
        use(session_value), into(t), into(clearance, has_clearance), into(temp), into(voltage);
    found.resize(t.size());
    for (std::size_t i = 0; i < t.size(); ++i) {
      found[i].t_s = t[i];
      if (has_clearance[i] == soci::i_ok) found[i].clearance_mm = clearance[i];
      found[i].temp_c = temp[i];
      found[i].voltage_v = voltage[i];
    }
    return found;
  });
}

std::vector<std::pair<std::int64_t, CalibrationRecord>> SociStore::calibrations() {
  return store_guarded(url_.shown, "reading calibrations", [&] {
    std::vector<std::pair<std::int64_t, CalibrationRecord>> found;
    CalibrationRecord row;
    long long id = 0, rows = 0;
    soci::indicator has_sensor = soci::i_null;
    soci::statement query =
        (sql_.prepare << "SELECT c.id, c.fitted_at, s.serial, c.model_json, c.fitted_rows,"
                         " c.rmse_mm FROM calibrations c LEFT JOIN sensors s ON s.id ="
                         " c.sensor_id ORDER BY c.id",
         into(id), into(row.fitted_at), into(row.sensor_serial, has_sensor), into(row.model_json),
         into(rows), into(row.rmse_mm));
    query.execute();
    while (query.fetch()) {
      if (has_sensor != soci::i_ok) row.sensor_serial.clear();
      row.rows = static_cast<std::uint64_t>(rows);
      found.emplace_back(id, row);
    }
    for (auto& [calibration_id, record] : found) {
      const long long calibration_value = calibration_id;
      long long session = 0;
      soci::statement sessions = (sql_.prepare << "SELECT session_id FROM calibration_sessions"
                                                  " WHERE calibration_id = :id ORDER BY session_id",
                                  use(calibration_value), into(session));
      sessions.execute();
      while (sessions.fetch()) record.session_ids.push_back(session);
    }
    return found;
  });
}

}  // namespace flange::host
