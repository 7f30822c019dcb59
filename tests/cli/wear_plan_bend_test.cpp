// SPDX-License-Identifier: MIT
// The plan from the estimates a store keeps is the same quantile of the same forecast as the plan
// re-estimated: on a synthetic fleet whose wear speeds up as the flange thins, the estimates
// written to the store and read back (the whole forecast input as JSON) give the fresh plan,
// date for date, at four risks; the same rows without the forecast input (an estimate kept
// before schema version 7) give the plan on the rate's quantile alone, and the page says so. On
// SQLite and on the PostgreSQL server of the StorePostgres fixture.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "forecast_input_json.h"
#include "host/synthetic_accelerating_fleet.h"
#include "limit_forecast.h"
#include "reprofiling_plan.h"
#include "store_test_fixture.h"
#include "store_test_records.h"
#include "stored_wear_estimates.h"

namespace flange::cli {
namespace {

using testing::StoreTest;

void expect_same_plan(const host::ReprofilingPlan& a, const host::ReprofilingPlan& b) {
  ASSERT_EQ(a.wheels.size(), b.wheels.size());
  for (std::size_t i = 0; i < a.wheels.size(); ++i) {
    EXPECT_EQ(a.wheels[i].wheel, b.wheels[i].wheel) << i;
    EXPECT_EQ(a.wheels[i].due_day, b.wheels[i].due_day) << i;
    EXPECT_EQ(a.wheels[i].due_date, b.wheels[i].due_date) << i;
    EXPECT_EQ(a.wheels[i].rate_at_risk_mm_per_1000km, b.wheels[i].rate_at_risk_mm_per_1000km) << i;
  }
  EXPECT_EQ(host::plan_csv(a), host::plan_csv(b));
}

class WearPlanBend : public StoreTest {};

TEST_P(WearPlanBend, TheStoredEstimatesPlanIsTheFreshOneOnAnAcceleratingFleet) {
  // The runs' times as a store keeps them (the stored plan needs the wheel's last run's).
  std::vector<host::WheelHistory> histories =
      testing::synthetic_accelerating_fleet(0.06, 1).histories;
  for (host::WheelHistory& history : histories) {
    for (host::WearObservation& run : history.runs) {
      run.at = host::date_of_day(run.day) + "T06:00:00Z";  // every run is at 06:00
    }
  }
  const host::FleetWear fleet = host::estimate_fleet_wear(histories, {});
  ASSERT_TRUE(fleet.acceleration.significant);
  auto store = open();
  for (int loco = 1; loco <= 5; ++loco) {
    store->record_run(
        testing::test_run("L0" + std::to_string(loco), testing::test_time(0), 100.0, 0.2));
  }
  store->write_wear_estimates(wear_estimate_set(fleet, store->marks(), "2026-06-01T00:00:00Z"));
  const auto stored = open()->wear_estimates();
  ASSERT_TRUE(stored.has_value());
  ASSERT_EQ(stored->wheels.size(), fleet.wheels.size());
  int bent = 0;
  for (const host::WheelEstimateRecord& e : stored->wheels) {
    bent += !e.forecast.empty() && forecast_input_of_json(e.forecast).acceleration_per_mm != 0.0;
  }
  EXPECT_GE(bent, 50);
  for (const double risk : {0.01, 0.05, 0.5, 0.8}) {
    const host::PlanRequest request{"2200-01-01", risk};
    const host::ReprofilingPlan fresh = host::plan_reprofiling(fleet, request);
    ASSERT_GE(fresh.wheels.size(), 50u);
    expect_same_plan(
        host::plan_reprofiling(plan_inputs(*stored), stored->critical_clearance_mm, request),
        fresh);
  }
  // The rows without the forecast input: the straight line's plan at the rate at risk, later on
  // the bent wheels.
  host::WearEstimateSet unbent = *stored;
  std::vector<host::PlanInput> straight;
  for (host::WheelEstimateRecord& e : unbent.wheels) e.forecast = "";
  for (const host::WheelWear& w : fleet.wheels) {
    host::PlanInput input = host::plan_input(w);
    input.forecast.reset();
    straight.push_back(input);
  }
  const host::PlanRequest even{"2200-01-01", 0.5};
  const host::ReprofilingPlan unbent_plan =
      host::plan_reprofiling(plan_inputs(unbent), unbent.critical_clearance_mm, even);
  expect_same_plan(unbent_plan,
                   host::plan_reprofiling(straight, fleet.critical_clearance_mm, even));
  const auto total_days = [](const host::ReprofilingPlan& plan) {
    double days = 0.0;
    for (const host::PlannedWheel& w : plan.wheels) days += w.due_day;
    return days;
  };
  EXPECT_GT(total_days(unbent_plan), total_days(host::plan_reprofiling(fleet, even)));
  EXPECT_TRUE(unbent_plan.wheels.at(0).on_rate_alone);
  EXPECT_NE(host::plan_html_section(unbent_plan).find("stored before schema version 7"),
            std::string::npos);
  EXPECT_EQ(host::plan_html_section(host::plan_reprofiling(fleet, even))
                .find("stored before schema version 7"),
            std::string::npos);
}

INSTANTIATE_TEST_SUITE_P(Backends, WearPlanBend,
                         ::testing::Values(testing::StoreBackendUnderTest::kSqlite,
                                           testing::StoreBackendUnderTest::kPostgresql),
                         testing::backend_param_name);

}  // namespace
}  // namespace flange::cli
