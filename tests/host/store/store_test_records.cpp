// SPDX-License-Identifier: MIT
#include "store_test_records.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

namespace flange::testing {

std::string test_time(int day, int hour) {
  return fmt::format("2026-01-{:02d}T{:02d}:00:00Z", day + 1, 6 + hour);
}

host::RunRecord test_run(const std::string& locomotive, const std::string& started_at,
                         double odometer_km, double wear_mm) {
  host::RunRecord run;
  run.locomotive = locomotive;
  run.started_at = started_at;
  run.distance_km = 300.0;
  run.odometer_km = odometer_km;
  run.coefficient_set = "coeffs/measurement_sos.json";
  run.coefficient_sha256 = std::string(64, 'a');
  run.engine = "model";
  run.sample_rate_hz = 100.0;
  run.rows = 12000;
  run.final_alarm = "warning";
  run.summary_json = R"({"engine": "model"})";
  for (int channel = 0; channel < 12; ++channel) {
    host::WheelRunResult wheel;
    wheel.axle = channel / 2 + 1;
    wheel.side = channel % 2 ? "right" : "left";
    wheel.channel = channel;
    wheel.wear_mm = wear_mm + 0.01 * channel;
    wheel.clearance_mm = 10.0 - wheel.wear_mm.value();
    wheel.temp_c = 20.0 + channel;
    wheel.samples = 1000;
    wheel.final_alarm = channel == 0 ? "warning" : "none";
    run.wheels.push_back(wheel);
    for (int km = 0; km < 3; ++km) {
      run.trace.push_back({wheel.axle, wheel.side, static_cast<double>(km), *wheel.clearance_mm,
                           wheel.temp_c, 333});
    }
  }
  run.alarms.push_back({1, "left", 12.5, "warning"});
  run.alarms.push_back({0, "", 13.0, "wear_step 0.73 mm"});
  return run;
}

namespace {

std::string key_of(const host::WheelKey& wheel) {
  return fmt::format("{}|{}|{}", wheel.locomotive, wheel.axle, wheel.side);
}

// The least-squares slope of wear against odometer (mm per 1000 km) of the points given.
std::optional<double> slope_of(const std::vector<host::WearPoint>& points) {
  if (points.size() < 2) return std::nullopt;
  double mx = 0.0, my = 0.0;
  for (const host::WearPoint& p : points) {
    mx += p.odometer_km;
    my += *p.wear_mm;
  }
  mx /= static_cast<double>(points.size());
  my /= static_cast<double>(points.size());
  double sxx = 0.0, sxy = 0.0;
  for (const host::WearPoint& p : points) {
    sxx += (p.odometer_km - mx) * (p.odometer_km - mx);
    sxy += (p.odometer_km - mx) * (*p.wear_mm - my);
  }
  if (sxx == 0.0) return std::nullopt;
  return 1000.0 * sxy / sxx;
}

}  // namespace

void write_mixed_history(host::Store& store) {
  store.upsert_wheel({{"idle", 1, "left"}, 0});
  store.record_maintenance(
      {{"M", 3, "right"}, test_time(2), 0.0, "reprofile", "before", std::nullopt});
  for (const int day : {4, 0, 2}) {
    store.record_run(test_run("M", test_time(day), 1000.0 * day, 0.2 * day));
  }
  std::vector<host::RunRecord> batch;
  for (int day = 5; day < 9; ++day) {
    batch.push_back(test_run("M", test_time(day), 1000.0 * day, 0.2 * day + 0.01 * (day % 3)));
    batch.push_back(test_run("N", test_time(day), 900.0 * day, 0.1 * day));
  }
  batch[3].wheels[2].wear_mm.reset();  // N axle 2 left: no wear figure that day
  store.record_runs(batch);
  store.record_maintenance(
      {{"M", 1, "left"}, test_time(6, 1), 6100.0, "reprofile", "lathe", std::nullopt});
  store.record_maintenance(
      {{"M", 1, "left"}, test_time(3), 3100.0, "inspect", "backdated", std::nullopt});
  // Tied in time with N's day 8 run, and one older than N's latest.
  store.record_runs(
      {test_run("N", test_time(8), 7200.0, 0.85), test_run("N", test_time(1), 900.0, 0.1)});
  store.record_run(test_run("M", test_time(9), 9000.0, 0.3));
}

void expect_fleet_table_matches_runs(host::Store& store) {
  std::map<std::string, std::string> last_maintenance;
  for (const host::StoredMaintenance& m : store.maintenance_events("")) {
    std::string& at = last_maintenance[key_of(m.event.wheel)];
    at = std::max(at, m.event.at);
  }
  std::map<std::string, std::uint64_t> alarms;
  for (const host::StoredAlarmEvent& e : store.alarm_events("")) {
    if (e.wheel) ++alarms[key_of(*e.wheel)];
  }
  const std::vector<host::FleetRow> fleet = store.fleet_table();
  ASSERT_EQ(fleet.size(), store.wheels().size());
  for (const host::FleetRow& row : fleet) {
    const std::string key = key_of(row.wheel);
    const std::vector<host::WearPoint> history = store.wear_history(row.wheel);
    const std::string since = last_maintenance[key];
    std::vector<host::WearPoint> fitted;
    std::uint64_t runs_since = 0;
    for (const host::WearPoint& p : history) {
      if (p.started_at < since) continue;
      ++runs_since;
      if (p.wear_mm) fitted.push_back(p);
    }
    EXPECT_EQ(row.runs, history.size()) << key;
    EXPECT_EQ(row.runs_since_maintenance, runs_since) << key;
    EXPECT_EQ(row.last_maintenance_at, since) << key;
    EXPECT_EQ(row.alarm_events, alarms[key]) << key;
    EXPECT_EQ(row.last_run_at, history.empty() ? "" : history.back().started_at) << key;
    if (!history.empty()) {
      EXPECT_EQ(row.last_wear_mm, history.back().wear_mm) << key;
      EXPECT_DOUBLE_EQ(row.last_odometer_km, history.back().odometer_km) << key;
    }
    const std::optional<double> slope = slope_of(fitted);
    ASSERT_EQ(row.wear_rate_mm_per_1000km.has_value(), slope.has_value()) << key;
    if (slope) {
      EXPECT_NEAR(*row.wear_rate_mm_per_1000km, *slope, 1e-6) << key;
    }
  }
}

}  // namespace flange::testing
