// SPDX-License-Identifier: MIT
// Every wheel's runs at once, for the wear estimate of a whole fleet: the wheels in one query,
// then their runs a block of wheels per query (a range of wheel ids through the index on
// (wheel, time), so no query's result grows with the fleet), fetched in bulk into columns.
#include <algorithm>
#include <map>

#include "soci_store.h"

namespace flange::host {

namespace {

using soci::into;
using soci::use;

constexpr long long kWheelsPerQuery = 500;   // a year of 500 wheels: about 180,000 rows
constexpr std::size_t kRowsPerFetch = 8192;  // rows per bulk fetch

// The runs of wheels first..last (ids) into `by_id`, in wheel then time order.
void fetch_runs(soci::session& sql, long long first, long long last,
                std::map<long long, WheelSeries>& by_id) {
  std::vector<long long> wheel(kRowsPerFetch), run(kRowsPerFetch);
  std::vector<std::string> at(kRowsPerFetch);
  std::vector<double> odometer(kRowsPerFetch), wear(kRowsPerFetch), clearance(kRowsPerFetch);
  std::vector<soci::indicator> has_wear(kRowsPerFetch), has_clearance(kRowsPerFetch);
  soci::statement query =
      (sql.prepare << "SELECT wheel_id, run_id, started_at, odometer_km, wear_mm, clearance_mm"
                      " FROM wheel_runs WHERE wheel_id BETWEEN :first AND :last"
                      " ORDER BY wheel_id, started_at, run_id",
       use(first, "first"), use(last, "last"), into(wheel), into(run), into(at), into(odometer),
       into(wear, has_wear), into(clearance, has_clearance));
  if (!query.execute(true)) return;
  do {
    for (std::size_t i = 0; i < wheel.size(); ++i) {
      SeriesPoint point;
      point.run_id = run[i];
      point.started_at = std::move(at[i]);
      point.odometer_km = odometer[i];
      if (has_wear[i] == soci::i_ok) point.wear_mm = wear[i];
      if (has_clearance[i] == soci::i_ok) point.clearance_mm = clearance[i];
      by_id[wheel[i]].points.push_back(std::move(point));
    }
    for (auto* column : {&wheel, &run}) column->resize(kRowsPerFetch);
    at.resize(kRowsPerFetch);
    for (auto* column : {&odometer, &wear, &clearance}) column->resize(kRowsPerFetch);
    has_wear.resize(kRowsPerFetch);
    has_clearance.resize(kRowsPerFetch);
  } while (query.fetch());
}

}  // namespace

std::vector<WheelSeries> SociStore::wear_series() {
  return store_guarded(url_.shown, "reading every wheel's runs", [&] {
    std::map<long long, WheelSeries> by_id;
    long long id = 0;
    WheelSeries row;
    soci::statement wheels =
        (sql_.prepare << "SELECT w.id, l.name, w.axle, w.side, w.channel FROM wheels w"
                         " JOIN locomotives l ON l.id = w.locomotive_id",
         into(id), into(row.wheel.wheel.locomotive), into(row.wheel.wheel.axle),
         into(row.wheel.wheel.side), into(row.wheel.channel));
    wheels.execute();
    while (wheels.fetch()) by_id[id] = row;
    if (!by_id.empty()) {
      const long long last = by_id.rbegin()->first;
      for (long long first = by_id.begin()->first; first <= last; first += kWheelsPerQuery) {
        fetch_runs(sql_, first, std::min(last, first + kWheelsPerQuery - 1), by_id);
      }
    }
    std::vector<WheelSeries> found;
    found.reserve(by_id.size());
    for (auto& [wheel_id, series] : by_id) found.push_back(std::move(series));
    std::sort(found.begin(), found.end(), [](const WheelSeries& a, const WheelSeries& b) {
      const WheelKey &x = a.wheel.wheel, &y = b.wheel.wheel;
      return std::tie(x.locomotive, x.axle, x.side) < std::tie(y.locomotive, y.axle, y.side);
    });
    return found;
  });
}

}  // namespace flange::host
