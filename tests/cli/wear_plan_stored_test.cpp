// SPDX-License-Identifier: MIT
// `flange wear --plan` from the estimates the store keeps: the first `flange wear` estimates
// every wheel and keeps the estimates; a plan asked for while nothing has been stored since is
// made from them (said on the page and on stdout) and is the plan re-estimated, date for date,
// at two risks; a run stored since makes the next plan re-estimate. On SQLite and on the
// PostgreSQL server of the StorePostgres fixture.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "flange_in_process.h"
#include "simulated_fleet_store.h"
#include "store.h"
#include "store_test_backends.h"
#include "store_test_fixture.h"
#include "test_files.h"

namespace flange::cli {
namespace {

namespace fs = std::filesystem;
using testing::FlangeOutcome;
using testing::run_flange_captured;
using testing::StoreBackendUnderTest;

std::string file_text(const fs::path& path) {
  std::ifstream file(path, std::ios::binary);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

class WearPlanStored : public ::testing::TestWithParam<StoreBackendUnderTest> {};

TEST_P(WearPlanStored, ThePlanFromTheStoredEstimatesIsThePlanReEstimated) {
  const auto fleet = testing::simulate_fleet_into_store("wear_plan_stored", GetParam(), 2, 60, 5);
  ASSERT_EQ(fleet.simulated.status, 0) << fleet.simulated.err;
  const fs::path& dir = fleet.dir;
  const std::string& store = fleet.store;
  const auto plan = [&](const std::string& out, const std::string& risk) {
    const FlangeOutcome outcome =
        run_flange_captured({"wear", "--store", store, "--out", (dir / out).string(), "--plan",
                             "--before", "2027-06-01", "--risk", risk});
    EXPECT_EQ(outcome.status, 0) << out << "\n" << outcome.err;
    return outcome;
  };
  // No estimates kept yet: every wheel estimated, the estimates kept.
  const FlangeOutcome first = plan("estimated", "0.05");
  EXPECT_NE(first.out.find("plan: re-estimating every wheel (the store holds no estimates)"),
            std::string::npos)
      << first.out;
  EXPECT_NE(first.out.find("kept the 24 wheels' estimates"), std::string::npos) << first.out;
  const std::string estimated_csv = file_text(dir / "estimated" / "plan.csv");
  ASSERT_GE(estimated_csv.size(), 100u) << "seed 5 should have wheels due:\n" << estimated_csv;
  // Nothing stored since: the plan from the stored estimates, the same dates.
  const FlangeOutcome stored = plan("stored", "0.05");
  EXPECT_NE(stored.out.find("the plan from the 24 wheels' estimates that flange wear stored"),
            std::string::npos)
      << stored.out;
  EXPECT_EQ(file_text(dir / "stored" / "plan.csv"), estimated_csv);
  EXPECT_NE(file_text(dir / "stored" / "index.html").find("not re-estimated"), std::string::npos);
  // At another risk too (a risk is the plan's, not the estimate's).
  const FlangeOutcome cautious_stored = plan("cautious_stored", "0.001");
  EXPECT_NE(cautious_stored.out.find("not re-estimated"), std::string::npos);
  // A plan at other limits cannot use them: re-estimated with those limits.
  const FlangeOutcome other_limits =
      run_flange_captured({"wear", "--store", store, "--out", (dir / "other_limits").string(),
                           "--plan", "--before", "2027-06-01", "--warning-mm", "7.5"});
  EXPECT_EQ(other_limits.status, 0) << other_limits.err;
  EXPECT_NE(other_limits.out.find("re-estimating every wheel (the stored estimates were made "
                                  "with other limits"),
            std::string::npos)
      << other_limits.out;
  // That run kept its own estimates (warning 7.5 mm); the default limits re-estimate again and
  // give the first plan, and at 0.001 the stored plan equals a re-estimated one.
  const FlangeOutcome back = plan("back", "0.001");
  EXPECT_NE(back.out.find("re-estimating"), std::string::npos) << back.out;
  EXPECT_EQ(file_text(dir / "back" / "plan.csv"), file_text(dir / "cautious_stored" / "plan.csv"));
  // A run stored after the estimates: the next plan re-estimates.
  host::RunRecord run;
  run.locomotive = "L01";
  run.started_at = "2026-12-31T06:00:00Z";
  run.odometer_km = 1e6;
  run.coefficient_set = "coeffs/measurement_sos/filter.json";
  run.coefficient_sha256 = std::string(64, 'c');
  run.engine = "model";
  run.sample_rate_hz = 100.0;
  host::open_store(store)->record_run(run);
  const FlangeOutcome after_run = plan("after_run", "0.05");
  EXPECT_NE(after_run.out.find("re-estimating every wheel (runs were stored after the estimates)"),
            std::string::npos)
      << after_run.out;
}

INSTANTIATE_TEST_SUITE_P(Backends, WearPlanStored,
                         ::testing::Values(StoreBackendUnderTest::kSqlite,
                                           StoreBackendUnderTest::kPostgresql),
                         testing::backend_param_name);

}  // namespace
}  // namespace flange::cli
