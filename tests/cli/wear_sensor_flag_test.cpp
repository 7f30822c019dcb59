// SPDX-License-Identifier: MIT
// The sensor flag `flange wear --store` carries from one estimate to the next in the store's
// wear estimates (host/wear/sensor_flag_latch.h), on a small fleet as a depot runs it: a drift
// the search flags is pending at first and latched when the search still flags it two weeks of
// data later; a healthy sensor's flag not confirmed then is dropped; a latched flag holds at a
// later estimate whose search does not flag the sensor, is printed with its dates, survives an
// odometer reset and is cleared by a sensor replacement recorded with `flange maintenance`. A
// flag in the store whose date is not a time is refused in one line. On SQLite and on the
// PostgreSQL server of the StorePostgres fixture.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>

#include "flange_in_process.h"
#include "simulated_fleet_store.h"
#include "store.h"
#include "store_test_backends.h"
#include "store_test_fixture.h"
#include "test_files.h"
#include "utc_time.h"
#include "wheel_history.h"

namespace flange::cli {
namespace {

namespace fs = std::filesystem;
using testing::FlangeOutcome;
using testing::run_flange_captured;
using testing::StoreBackendUnderTest;

// `at` moved by `days` (ISO 8601 UTC).
std::string days_after(const std::string& at, double days) {
  return format_utc_time((host::day_of_iso_time(at) + days) * 86400.0);
}

struct Wheel {
  std::string locomotive, side, last_run_at;
  int axle = 0;
};

nlohmann::json wheel_json(const fs::path& out, const Wheel& wheel) {
  const nlohmann::json wear = nlohmann::json::parse(std::ifstream(out / "wear.json"));
  for (const auto& w : wear.at("wheels")) {
    if (w.at("locomotive") == wheel.locomotive && w.at("axle") == wheel.axle &&
        w.at("side") == wheel.side) {
      return w;
    }
  }
  ADD_FAILURE() << "no wheel " << wheel.locomotive << " axle " << wheel.axle << " " << wheel.side;
  return {};
}

// Sets a wheel's sensor flag in the store's kept estimates, as an earlier estimate would have.
void keep_flag(const std::string& store, const Wheel& wheel, const std::string& first,
               const std::string& confirmed) {
  const auto opened = host::open_store(store);
  host::WearEstimateSet set = opened->wear_estimates().value();
  for (host::WheelEstimateRecord& e : set.wheels) {
    if (e.wheel == host::WheelKey{wheel.locomotive, wheel.axle, wheel.side}) {
      e.sensor_flag_first = first;
      e.sensor_flag_confirmed = confirmed;
    }
  }
  opened->write_wear_estimates(set);
}

// From the first estimate: the sensor the search flags (pending from now on) and two healthy
// wheels never reprofiled.
struct Wheels {
  Wheel drifting, healthy, other;
};

Wheels wheels_of_first_estimate(const fs::path& out) {
  Wheels found;
  const nlohmann::json first = nlohmann::json::parse(std::ifstream(out / "wear.json"));
  for (const auto& w : first.at("wheels")) {
    const Wheel wheel{w.at("locomotive"), w.at("side"), w.at("runs").back().at("at"), w.at("axle")};
    if (!w.at("sensor_fault").is_null()) {
      found.drifting = wheel;
      // First flagged now: pending, its date the wheel's last run.
      EXPECT_EQ(w.at("sensor_flag").at("first_flagged"), wheel.last_run_at);
      EXPECT_FALSE(w.at("sensor_flag").at("latched").get<bool>());
    } else if (w.at("status") == "ok" && w.at("reprofilings").empty()) {
      EXPECT_TRUE(w.at("sensor_flag").is_null());
      (found.healthy.locomotive.empty() ? found.healthy : found.other) = wheel;
    }
  }
  return found;
}

class WearSensorFlag : public ::testing::TestWithParam<StoreBackendUnderTest> {};

TEST_P(WearSensorFlag, IsLatchedOnceConfirmedHeldAndClearedByTheDepot) {
  // Two locomotives over 45 days, seed 11: a drifting sensor the search flags, none other.
  const auto fleet = testing::simulate_fleet_into_store("wear_sensor_flag", GetParam(), 2, 45, 11);
  ASSERT_EQ(fleet.simulated.status, 0) << fleet.simulated.err;
  const fs::path& dir = fleet.dir;
  const std::string& store = fleet.store;
  const auto wear = [&](const std::string& out) {
    const FlangeOutcome outcome =
        run_flange_captured({"wear", "--store", store, "--out", (dir / out).string()});
    EXPECT_EQ(outcome.status, 0) << out << "\n" << outcome.err;
    return outcome;
  };
  wear("first");
  const auto [drifting, healthy, other] = wheels_of_first_estimate(dir / "first");
  ASSERT_FALSE(drifting.locomotive.empty()) << "seed 11 should flag its drifting sensor";
  ASSERT_FALSE(other.locomotive.empty()) << "seed 11 should have wheels never reprofiled";
  // Not yet two weeks of data since the first flag: still pending.
  wear("again");
  EXPECT_FALSE(wheel_json(dir / "again", drifting).at("sensor_flag").at("latched").get<bool>());
  // Flagged 20 days earlier and still flagged: latched. A healthy sensor flagged 20 days earlier
  // that the search does not flag now: dropped. A healthy sensor latched earlier: held.
  keep_flag(store, drifting, days_after(drifting.last_run_at, -20.0), "");
  keep_flag(store, other, days_after(other.last_run_at, -20.0), "");
  const std::string since = days_after(healthy.last_run_at, -30.0);
  keep_flag(store, healthy, since, days_after(healthy.last_run_at, -16.0));
  const FlangeOutcome latched = wear("latched");
  const nlohmann::json drift = wheel_json(dir / "latched", drifting);
  EXPECT_EQ(drift.at("sensor_flag").at("confirmed"), drifting.last_run_at);
  EXPECT_EQ(drift.at("status"), "sensor fault");
  EXPECT_TRUE(wheel_json(dir / "latched", other).at("sensor_flag").is_null());
  const nlohmann::json held = wheel_json(dir / "latched", healthy);
  EXPECT_TRUE(held.at("sensor_fault").is_null()) << "the search flags no healthy sensor here";
  EXPECT_EQ(held.at("status"), "sensor fault");
  EXPECT_TRUE(held.at("sensor_flag").at("latched").get<bool>());
  EXPECT_NE(
      latched.out.find(fmt::format("{} axle {} {}: sensor flagged since {}", healthy.locomotive,
                                   healthy.axle, healthy.side, since.substr(0, 10))),
      std::string::npos)
      << latched.out;
  // Held at the next estimate; an odometer reset is no act on the sensor.
  host::open_store(store)->record_maintenance({{healthy.locomotive, healthy.axle, healthy.side},
                                               days_after(healthy.last_run_at, 0.5),
                                               0.0,
                                               "odometer_reset",
                                               "",
                                               std::nullopt});
  wear("held");
  EXPECT_EQ(wheel_json(dir / "held", healthy).at("status"), "sensor fault");
  EXPECT_EQ(wheel_json(dir / "held", drifting).at("status"), "sensor fault");
  // The depot replaces the sensor: the flag is cleared.
  const FlangeOutcome replaced =
      run_flange_captured({"maintenance", "--store", store, "--locomotive", healthy.locomotive,
                           "--kind", "sensor_replaced", "--axle", std::to_string(healthy.axle),
                           "--side", healthy.side, "--at", days_after(healthy.last_run_at, 0.6)});
  ASSERT_EQ(replaced.status, 0) << replaced.err;
  wear("cleared");
  const nlohmann::json cleared = wheel_json(dir / "cleared", healthy);
  EXPECT_TRUE(cleared.at("sensor_flag").is_null());
  EXPECT_NE(cleared.at("status"), "sensor fault");
  EXPECT_EQ(wheel_json(dir / "cleared", drifting).at("status"), "sensor fault");
  // A flag date in the store that is not a time: one line naming it, nothing written.
  keep_flag(store, healthy, "2027-13-01T06:00:00Z", "");
  const FlangeOutcome refused =
      run_flange_captured({"wear", "--store", store, "--out", (dir / "refused").string()});
  EXPECT_EQ(refused.status, 1);
  EXPECT_NE(refused.err.find(fmt::format("wheel_estimates of {} axle {} {}: sensor flag: "
                                         "'2027-13-01T06:00:00Z' is not a UTC time",
                                         healthy.locomotive, healthy.axle, healthy.side)),
            std::string::npos)
      << refused.err;
  EXPECT_EQ(std::count(refused.err.begin(), refused.err.end(), '\n'), 1) << refused.err;
  EXPECT_FALSE(fs::exists(dir / "refused"));
}

INSTANTIATE_TEST_SUITE_P(Backends, WearSensorFlag,
                         ::testing::Values(StoreBackendUnderTest::kSqlite,
                                           StoreBackendUnderTest::kPostgresql),
                         testing::backend_param_name);

}  // namespace
}  // namespace flange::cli
