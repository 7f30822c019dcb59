// SPDX-License-Identifier: MIT
// The fleet table: every wheel's runs summarised by one aggregate query (the database does the
// work, one row per wheel comes back), the wear rate from least-squares sums.
#include "soci_store.h"

namespace flange::host {

namespace {

using soci::into;

// Runs after the wheel's latest maintenance event ("since") feed the rate; x is the odometer,
// y the wear. Sums come back; the slope is computed here.
constexpr const char* kFleetQuery =
    "WITH last_maintenance AS (SELECT wheel_id, MAX(at) AS at FROM maintenance_events"
    "  GROUP BY wheel_id),"
    " per_run AS (SELECT w.wheel_id, w.started_at, w.odometer_km AS x, w.wear_mm AS y,"
    "  CASE WHEN m.at IS NULL OR w.started_at >= m.at THEN 1 ELSE 0 END AS since"
    "  FROM wheel_runs w LEFT JOIN last_maintenance m ON m.wheel_id = w.wheel_id),"
    " fit AS (SELECT wheel_id, COUNT(*) AS runs, SUM(since) AS runs_since,"
    "  MAX(started_at) AS last_at, MAX(x) AS last_x,"
    "  SUM(CASE WHEN since = 1 AND y IS NOT NULL THEN 1 ELSE 0 END) AS n,"
    "  SUM(CASE WHEN since = 1 AND y IS NOT NULL THEN x ELSE 0 END) AS sx,"
    "  SUM(CASE WHEN since = 1 AND y IS NOT NULL THEN y ELSE 0 END) AS sy,"
    "  SUM(CASE WHEN since = 1 AND y IS NOT NULL THEN x * x ELSE 0 END) AS sxx,"
    "  SUM(CASE WHEN since = 1 AND y IS NOT NULL THEN x * y ELSE 0 END) AS sxy"
    "  FROM per_run GROUP BY wheel_id),"
    " alarms AS (SELECT wheel_id, COUNT(*) AS events FROM alarm_events"
    "  WHERE wheel_id IS NOT NULL GROUP BY wheel_id)"
    " SELECT l.name, h.axle, h.side, COALESCE(f.runs, 0), COALESCE(f.runs_since, 0),"
    "  COALESCE(f.last_at, ''), COALESCE(f.last_x, 0),"
    // The latest run's wear: one index seek per wheel (wheel_runs_by_wheel).
    "  (SELECT t.wear_mm FROM wheel_runs t WHERE t.wheel_id = h.id"
    "   ORDER BY t.started_at DESC, t.run_id DESC LIMIT 1),"
    "  COALESCE(f.n, 0), COALESCE(f.sx, 0), COALESCE(f.sy, 0), COALESCE(f.sxx, 0),"
    "  COALESCE(f.sxy, 0), COALESCE(m.at, ''), COALESCE(a.events, 0)"
    " FROM wheels h JOIN locomotives l ON l.id = h.locomotive_id"
    " LEFT JOIN fit f ON f.wheel_id = h.id"
    " LEFT JOIN last_maintenance m ON m.wheel_id = h.id"
    " LEFT JOIN alarms a ON a.wheel_id = h.id"
    " ORDER BY l.name, h.axle, h.side";

struct FitSums {
  long long n = 0;
  double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;

  // mm per 1000 km; none without two runs at distinct odometers.
  std::optional<double> rate() const {
    if (n < 2) return std::nullopt;
    const double count = static_cast<double>(n);
    const double sxx_centred = sxx - sx * sx / count;
    if (!(sxx_centred > 1e-9 * (1.0 + sxx))) return std::nullopt;
    return 1000.0 * (sxy - sx * sy / count) / sxx_centred;
  }
};

}  // namespace

std::vector<FleetRow> SociStore::fleet_table() {
  return store_guarded(url_.shown, "reading the fleet table", [&] {
    std::vector<FleetRow> found;
    FleetRow row;
    FitSums sums;
    long long runs = 0, runs_since = 0, events = 0;
    double last_wear = 0.0;
    soci::indicator has_last_wear = soci::i_null;
    soci::statement query =
        (sql_.prepare << kFleetQuery, into(row.wheel.locomotive), into(row.wheel.axle),
         into(row.wheel.side), into(runs), into(runs_since), into(row.last_run_at),
         into(row.last_odometer_km), into(last_wear, has_last_wear), into(sums.n), into(sums.sx),
         into(sums.sy), into(sums.sxx), into(sums.sxy), into(row.last_maintenance_at),
         into(events));
    query.execute();
    while (query.fetch()) {
      row.runs = static_cast<std::uint64_t>(runs);
      row.runs_since_maintenance = static_cast<std::uint64_t>(runs_since);
      row.alarm_events = static_cast<std::uint64_t>(events);
      row.last_wear_mm.reset();
      if (has_last_wear == soci::i_ok) row.last_wear_mm = last_wear;
      row.wear_rate_mm_per_1000km = sums.rate();
      found.push_back(row);
    }
    return found;
  });
}

}  // namespace flange::host
