// SPDX-License-Identifier: MIT
#include "wheel_fit_table.h"

#include <fmt/format.h>

#include <algorithm>

namespace flange::host {

namespace {

// A run feeds a wheel's fit when it is at or after the wheel's latest maintenance (since_at is
// '' without one: every time sorts after it) and has a wear figure; x is the odometer, y the
// wear.
constexpr const char* kFits = "w.started_at >= f.since_at AND w.wear_mm IS NOT NULL";

// The batch's sums per wheel, the wheel rows chosen by `filter` (alias w).
std::string sums_of(const std::string& filter) {
  return fmt::format(
      "SELECT w.wheel_id, COUNT(*) AS runs,"
      " SUM(CASE WHEN w.started_at >= f.since_at THEN 1 ELSE 0 END) AS runs_since,"
      " SUM(CASE WHEN {0} THEN 1 ELSE 0 END) AS n,"
      " SUM(CASE WHEN {0} THEN w.odometer_km ELSE 0 END) AS sx,"
      " SUM(CASE WHEN {0} THEN w.wear_mm ELSE 0 END) AS sy,"
      " SUM(CASE WHEN {0} THEN w.odometer_km * w.odometer_km ELSE 0 END) AS sxx,"
      " SUM(CASE WHEN {0} THEN w.odometer_km * w.wear_mm ELSE 0 END) AS sxy,"
      " SUM(CASE WHEN {0} THEN w.wear_mm * w.wear_mm ELSE 0 END) AS syy"
      " FROM wheel_runs w JOIN wheel_fit f ON f.wheel_id = w.wheel_id WHERE {1}"
      " GROUP BY w.wheel_id",
      kFits, filter);
}

// The statements that add runs to the sums, the runs chosen by `runs` with "{a}" standing for
// a table alias (w, v, e): rows for new wheels, the sums, the latest run, the alarm count.
std::vector<std::string> add_statements(const std::string& runs) {
  const auto on = [&](const char* alias) {
    std::string text = runs;
    for (auto at = text.find("{a}"); at != std::string::npos; at = text.find("{a}")) {
      text.replace(at, 3, alias);
    }
    return text;
  };
  return {
      "INSERT INTO wheel_fit (wheel_id) SELECT DISTINCT w.wheel_id FROM wheel_runs w WHERE " +
          on("w") + " ON CONFLICT (wheel_id) DO NOTHING",
      "INSERT INTO wheel_fit (wheel_id) SELECT DISTINCT e.wheel_id FROM alarm_events e"
      " WHERE e.wheel_id IS NOT NULL AND " +
          on("e") + " ON CONFLICT (wheel_id) DO NOTHING",
      "UPDATE wheel_fit SET runs = wheel_fit.runs + d.runs,"
      " runs_since = wheel_fit.runs_since + d.runs_since, n = wheel_fit.n + d.n,"
      " sx = wheel_fit.sx + d.sx, sy = wheel_fit.sy + d.sy, sxx = wheel_fit.sxx + d.sxx,"
      " sxy = wheel_fit.sxy + d.sxy, syy = wheel_fit.syy + d.syy FROM (" +
          sums_of(on("w")) + ") AS d WHERE wheel_fit.wheel_id = d.wheel_id",
      // The batch's latest run of each wheel, when it is later than the one kept.
      "UPDATE wheel_fit SET last_at = d.started_at, last_run_id = d.run_id,"
      " last_odometer_km = d.odometer_km, last_wear_mm = d.wear_mm FROM (SELECT w.wheel_id,"
      " w.started_at, w.run_id, w.odometer_km, w.wear_mm FROM wheel_runs w WHERE " +
          on("w") +
          " AND NOT EXISTS (SELECT 1 FROM wheel_runs v WHERE v.wheel_id = w.wheel_id AND " +
          on("v") +
          " AND (v.started_at > w.started_at OR (v.started_at = w.started_at AND v.run_id >"
          " w.run_id)))) AS d WHERE wheel_fit.wheel_id = d.wheel_id AND (d.started_at >"
          " wheel_fit.last_at OR (d.started_at = wheel_fit.last_at AND d.run_id >"
          " wheel_fit.last_run_id))",
      "UPDATE wheel_fit SET alarm_events = wheel_fit.alarm_events + d.events FROM (SELECT"
      " e.wheel_id, COUNT(*) AS events FROM alarm_events e WHERE e.wheel_id IS NOT NULL AND " +
          on("e") + " GROUP BY e.wheel_id) AS d WHERE wheel_fit.wheel_id = d.wheel_id",
  };
}

}  // namespace

std::vector<std::string> wheel_fit_migration() {
  std::vector<std::string> steps = {
      "CREATE TABLE wheel_fit (wheel_id BIGINT PRIMARY KEY REFERENCES wheels (id),"
      " runs BIGINT NOT NULL DEFAULT 0, last_at TEXT NOT NULL DEFAULT '',"
      " last_run_id BIGINT NOT NULL DEFAULT 0, last_odometer_km {real} NOT NULL DEFAULT 0,"
      " last_wear_mm {real}, since_at TEXT NOT NULL DEFAULT '',"
      " runs_since BIGINT NOT NULL DEFAULT 0, n BIGINT NOT NULL DEFAULT 0,"
      " sx {real} NOT NULL DEFAULT 0, sy {real} NOT NULL DEFAULT 0,"
      " sxx {real} NOT NULL DEFAULT 0, sxy {real} NOT NULL DEFAULT 0,"
      " syy {real} NOT NULL DEFAULT 0, alarm_events BIGINT NOT NULL DEFAULT 0)",
      "INSERT INTO wheel_fit (wheel_id) SELECT id FROM wheels",
      "UPDATE wheel_fit SET since_at = d.at FROM (SELECT wheel_id, MAX(at) AS at FROM"
      " maintenance_events GROUP BY wheel_id) AS d WHERE wheel_fit.wheel_id = d.wheel_id",
  };
  // Every run stored so far, added to sums that start at zero.
  for (std::string& statement : add_statements("1 = 1")) steps.push_back(std::move(statement));
  return steps;
}

void refit_wheel_since_maintenance(soci::session& sql, long long wheel_id) {
  long long a = wheel_id, b = wheel_id;
  sql << "INSERT INTO wheel_fit (wheel_id) VALUES (:a) ON CONFLICT (wheel_id) DO NOTHING",
      soci::use(a, "a");
  sql << "UPDATE wheel_fit SET since_at = (SELECT MAX(at) FROM maintenance_events"
         " WHERE wheel_id = :a), runs_since = 0, n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0,"
         " syy = 0 WHERE wheel_id = :b",
      soci::use(a, "a"), soci::use(b, "b");
  // The sums since the (new) latest event, from that wheel's runs.
  sql << "UPDATE wheel_fit SET runs_since = d.runs_since, n = d.n, sx = d.sx, sy = d.sy,"
         " sxx = d.sxx, sxy = d.sxy, syy = d.syy FROM (" +
             sums_of("w.wheel_id = :a") + ") AS d WHERE wheel_fit.wheel_id = d.wheel_id",
      soci::use(a, "a");
}

}  // namespace flange::host
