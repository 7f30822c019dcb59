// SPDX-License-Identifier: MIT
// The wear estimates a store keeps (schema version 4; the sensor flags of 6, the forecast's bend
// of 7): read back exactly as written (a number that is not finite as NaN), a new set replacing
// the last, and the marks that say whether they are current moving with every run, maintenance
// event and calibration stored; an older store's estimates migrated with what it lacks empty.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <utility>

#include "store_migration.h"
#include "store_test_fixture.h"
#include "store_test_records.h"

namespace flange::testing {
namespace {

host::WheelEstimateRecord estimate(const std::string& locomotive, int axle, double rate) {
  host::WheelEstimateRecord e;
  e.wheel = {locomotive, axle, "left"};
  e.channel = 2 * (axle - 1);
  e.status = "ok";
  e.has_fit = true;
  e.segment_start = "2026-01-01T06:00:00Z";
  e.last_run_at = "2026-03-01T06:00:00Z";
  e.last_run_day = 20513.25;
  e.rate_mm_per_1000km = rate;
  e.rate_low = rate - 0.1 / 3.0;
  e.rate_high = rate + 0.1 / 7.0;
  e.rate_se = 1.0 / 97.0;
  e.rate_dof = 17;
  e.fit_dof = 58;
  e.clearance_now_mm = 3.0 + 1.0 / 3.0;
  e.wear_now_mm = 1.0 / 3.0;
  e.km_per_day = 301.123456789012345;
  e.km_per_day_se = 2.5e-3;
  e.day_km_sd = std::nan("");
  e.km_per_day_dof = 59;
  e.clearance_now_se_mm = 1e-17;
  e.clearance_rate_covariance = -3.3e-9;
  e.critical_date = "2027-02-03";
  e.warning_date = "reached";
  return e;
}

// An estimate of two wheels of L1 (rates 0.1 and 0.25) with the limits they were made at; the
// store's marks are the caller's.
host::WearEstimateSet two_wheel_estimates() {
  host::WearEstimateSet set;
  set.made_at = "2026-03-02T01:00:00Z";
  set.warning_clearance_mm = 8.0;
  set.critical_clearance_mm = 10.0;
  set.max_step_mm = 0.5;
  set.wheels = {estimate("L1", 1, 0.1), estimate("L1", 2, 0.25)};
  return set;
}

void expect_same(const host::WheelEstimateRecord& a, const host::WheelEstimateRecord& b) {
  EXPECT_EQ(a.wheel.locomotive, b.wheel.locomotive);
  EXPECT_EQ(a.wheel.axle, b.wheel.axle);
  EXPECT_EQ(a.channel, b.channel);
  EXPECT_EQ(a.status, b.status);
  EXPECT_EQ(a.has_fit, b.has_fit);
  EXPECT_EQ(a.segment_start, b.segment_start);
  EXPECT_EQ(a.last_run_at, b.last_run_at);
  EXPECT_EQ(a.last_run_day, b.last_run_day);
  EXPECT_EQ(a.rate_mm_per_1000km, b.rate_mm_per_1000km);
  EXPECT_EQ(a.rate_low, b.rate_low);
  EXPECT_EQ(a.rate_high, b.rate_high);
  EXPECT_EQ(a.rate_se, b.rate_se);
  EXPECT_EQ(a.rate_dof, b.rate_dof);
  EXPECT_EQ(a.fit_dof, b.fit_dof);
  EXPECT_EQ(a.clearance_now_mm, b.clearance_now_mm);
  EXPECT_EQ(a.wear_now_mm, b.wear_now_mm);
  EXPECT_EQ(a.km_per_day, b.km_per_day);
  EXPECT_EQ(a.km_per_day_se, b.km_per_day_se);
  EXPECT_EQ(std::isnan(a.day_km_sd), std::isnan(b.day_km_sd));
  EXPECT_EQ(a.km_per_day_dof, b.km_per_day_dof);
  EXPECT_EQ(a.clearance_now_se_mm, b.clearance_now_se_mm);
  EXPECT_EQ(a.clearance_rate_covariance, b.clearance_rate_covariance);
  EXPECT_EQ(a.critical_reached, b.critical_reached);
  EXPECT_EQ(a.critical_date, b.critical_date);
  EXPECT_EQ(a.warning_date, b.warning_date);
  EXPECT_EQ(a.sensor_flag_first, b.sensor_flag_first);
  EXPECT_EQ(a.sensor_flag_confirmed, b.sensor_flag_confirmed);
  EXPECT_EQ(a.forecast, b.forecast);
}

// The dates' forecast input kept as text (schema version 7; cli/forecast_input_json.h writes it),
// with digits and characters no rounding or quoting may change.
void keep_forecast(host::WheelEstimateRecord& e, double b) {
  e.forecast = fmt::format(R"({{"acceleration_per_mm":{:.17g},"note":"it's \"kept\""}})", b);
}

// The two wheels' estimates a store written at an older schema version holds once opened at the
// present one, with the marks `set` was written with; empty when it holds none.
std::vector<host::WheelEstimateRecord> migrated_wheels(host::Store& store,
                                                       const host::WearEstimateSet& set) {
  const auto migrated = store.wear_estimates();
  if (!migrated.has_value()) {
    ADD_FAILURE() << "no estimates once opened at schema version " << store.schema_version();
    return {};
  }
  EXPECT_EQ(migrated->marks, set.marks);
  return migrated->wheels;
}

TEST_P(StoreTest, KeepsTheWearEstimatesExactlyAndTheMarksMoveWithEveryWrite) {
  auto store = open();
  EXPECT_FALSE(store->wear_estimates().has_value());
  EXPECT_EQ(store->marks(), host::StoreMarks{});
  const auto first = store->record_run(test_run("L1", test_time(0), 100.0, 0.2));
  EXPECT_EQ(store->marks().last_run_id, first);
  host::WearEstimateSet set = two_wheel_estimates();
  set.marks = store->marks();
  set.wheels[0] = estimate("L1", 1, 0.1 + 1e-13);
  set.wheels[0].sensor_flag_first = "2026-02-01T06:00:00Z";  // a latched sensor flag
  set.wheels[0].sensor_flag_confirmed = "2026-02-15T06:00:00Z";
  set.wheels[1].sensor_flag_first = "2026-02-20T06:00:00Z";  // a pending one
  keep_forecast(set.wheels[0], 0.06 + 1.0 / 7919.0);         // the other wheel's none: ''
  store->write_wear_estimates(set);
  const auto read = open()->wear_estimates();
  ASSERT_TRUE(read.has_value());
  EXPECT_EQ(read->made_at, set.made_at);
  EXPECT_EQ(read->marks, set.marks);
  EXPECT_EQ(read->critical_clearance_mm, 10.0);
  ASSERT_EQ(read->wheels.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) expect_same(read->wheels[i], set.wheels[i]);
  // A new set replaces the last.
  set.wheels = {estimate("L1", 3, 0.3)};
  store->write_wear_estimates(set);
  ASSERT_EQ(store->wear_estimates()->wheels.size(), 1u);
  EXPECT_EQ(store->wear_estimates()->wheels[0].wheel.axle, 3);
  // A wheel the store does not hold is refused, the last set kept.
  set.wheels = {estimate("L9", 1, 0.3)};
  EXPECT_THROW(store->write_wear_estimates(set), host::StoreError);
  EXPECT_EQ(store->wear_estimates()->wheels[0].wheel.axle, 3);
  // Every write the estimate depends on moves the marks.
  const host::StoreMarks before = store->marks();
  store->record_maintenance(
      {{"L1", 1, "left"}, test_time(1), 150.0, "reprofile", "", std::nullopt});
  EXPECT_GT(store->marks().last_maintenance_id, before.last_maintenance_id);
  store->record_calibration({"2026-03-03T00:00:00Z", "", "{}", 10, 0.01, {}});
  EXPECT_GT(store->marks().last_calibration_id, before.last_calibration_id);
  store->record_run(test_run("L1", test_time(2), 200.0, 0.3));
  EXPECT_GT(store->marks().last_run_id, before.last_run_id);
}

// A version 5 store's estimates (no sensor flags) open at the current version with their rows and
// no flag, and keep the flags written from then on.
TEST_P(StoreTest, AVersion5StoresEstimatesOpenWithNoSensorFlagAndKeepTheFlagsWrittenThen) {
  host::WearEstimateSet set = two_wheel_estimates();
  {
    const auto old = host::open_store_at_schema_version(url(), 5);
    old->record_run(test_run("L1", test_time(0), 100.0, 0.2));
    set.marks = old->marks();
    old->write_wear_estimates(set);
    ASSERT_EQ(old->wear_estimates()->wheels.size(), 2u);
  }
  auto store = open();
  ASSERT_EQ(store->schema_version(), host::kStoreSchemaVersion);
  const std::vector<host::WheelEstimateRecord> migrated = migrated_wheels(*store, set);
  ASSERT_EQ(migrated.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) expect_same(migrated[i], set.wheels[i]);
  EXPECT_EQ(migrated[0].sensor_flag_first, "");
  set.wheels[1].sensor_flag_first = "2026-02-01T06:00:00Z";
  set.wheels[1].sensor_flag_confirmed = "2026-02-15T06:00:00Z";
  store->write_wear_estimates(set);
  expect_same(open()->wear_estimates()->wheels.at(1), set.wheels[1]);
}

// A version 6 store's estimates (no forecast input) open at version 7 with their rows and no
// forecast ('': planned on the rate's quantile alone), and keep the forecast written from then on.
TEST_P(StoreTest, AVersion6StoresEstimatesOpenWithNoForecastAndKeepTheForecastWrittenThen) {
  host::WearEstimateSet set = two_wheel_estimates();
  set.wheels[0].sensor_flag_first = "2026-02-01T06:00:00Z";
  keep_forecast(set.wheels[1], 0.05);
  {
    const auto old = host::open_store_at_schema_version(url(), 6);
    old->record_run(test_run("L1", test_time(0), 100.0, 0.2));
    set.marks = old->marks();
    old->write_wear_estimates(set);
    const auto kept = old->wear_estimates();
    ASSERT_EQ(kept->wheels.size(), 2u);
    EXPECT_EQ(kept->wheels[1].forecast, "");  // version 6 has no column
  }
  auto store = open();
  ASSERT_EQ(store->schema_version(), host::kStoreSchemaVersion);
  const std::vector<host::WheelEstimateRecord> migrated = migrated_wheels(*store, set);
  ASSERT_EQ(migrated.size(), 2u);
  host::WearEstimateSet unkept = set;
  unkept.wheels[1].forecast = "";
  for (std::size_t i = 0; i < 2; ++i) expect_same(migrated[i], unkept.wheels[i]);
  store->write_wear_estimates(set);
  expect_same(open()->wear_estimates()->wheels.at(1), set.wheels[1]);
}

}  // namespace
}  // namespace flange::testing
