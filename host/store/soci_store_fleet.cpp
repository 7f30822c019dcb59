// SPDX-License-Identifier: MIT
// The fleet table: one row per wheel read from the per-wheel sums the writes keep (wheel_fit,
// wheel_fit_table.h), so its cost does not grow with the history; the wear rate and its
// standard error from the least-squares sums.
#include <algorithm>
#include <cmath>

#include "soci_store.h"

namespace flange::host {

namespace {

using soci::into;

constexpr const char* kFleetQuery =
    "SELECT l.name, h.axle, h.side, COALESCE(f.runs, 0), COALESCE(f.runs_since, 0),"
    " COALESCE(f.last_at, ''), COALESCE(f.last_odometer_km, 0), f.last_wear_mm,"
    " COALESCE(f.n, 0), COALESCE(f.sx, 0), COALESCE(f.sy, 0), COALESCE(f.sxx, 0),"
    " COALESCE(f.sxy, 0), COALESCE(f.syy, 0), COALESCE(f.since_at, ''),"
    " COALESCE(f.alarm_events, 0)"
    " FROM wheels h JOIN locomotives l ON l.id = h.locomotive_id"
    " LEFT JOIN wheel_fit f ON f.wheel_id = h.id"
    " ORDER BY l.name, h.axle, h.side";

struct FitSums {
  long long n = 0;
  double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0, syy = 0.0;

  // mm per 1000 km; none without two runs at distinct odometers.
  std::optional<double> rate() const {
    if (n < 2) return std::nullopt;
    const double count = static_cast<double>(n);
    const double sxx_centred = sxx - sx * sx / count;
    if (!(sxx_centred > 1e-9 * (1.0 + sxx))) return std::nullopt;
    return 1000.0 * (sxy - sx * sy / count) / sxx_centred;
  }

  // The rate's standard error (mm per 1000 km); none without three runs.
  std::optional<double> rate_se() const {
    const std::optional<double> slope = rate();
    if (!slope || n < 3) return std::nullopt;
    const double count = static_cast<double>(n);
    const double sxx_centred = sxx - sx * sx / count;
    const double syy_centred = syy - sy * sy / count;
    const double sxy_centred = sxy - sx * sy / count;
    const double rss = std::max(0.0, syy_centred - sxy_centred * sxy_centred / sxx_centred);
    return 1000.0 * std::sqrt(rss / (count - 2.0) / sxx_centred);
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
         into(sums.sy), into(sums.sxx), into(sums.sxy), into(sums.syy),
         into(row.last_maintenance_at), into(events));
    query.execute();
    while (query.fetch()) {
      row.runs = static_cast<std::uint64_t>(runs);
      row.runs_since_maintenance = static_cast<std::uint64_t>(runs_since);
      row.alarm_events = static_cast<std::uint64_t>(events);
      row.last_wear_mm.reset();
      if (has_last_wear == soci::i_ok) row.last_wear_mm = last_wear;
      row.wear_rate_mm_per_1000km = sums.rate();
      row.wear_rate_se = sums.rate_se();
      found.push_back(row);
    }
    return found;
  });
}

}  // namespace flange::host
