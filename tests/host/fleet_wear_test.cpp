// SPDX-License-Identifier: MIT
// The fleet wear estimator on histories with known answers: rates per 1000 km with intervals
// that hold them, a reprofiling found from the jump back, a sensor drifting away from its axle
// partner flagged (and its drift fitted out of its rate), healthy sensors left alone, and the
// forecast of the warning clearance.
#include "fleet_wear.h"
#include "limit_forecast.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

namespace flange::host {
namespace {

struct Truth {
  double rate_left = 0.08, rate_right = 0.04;  // mm per 1000 km
  std::optional<int> reprofile_day;            // both wheels back to 2 mm that day
  std::optional<int> drift_from_day;           // the right sensor drifts from then ...
  double drift_mm_per_day = 0.01;              // ... at this rate
  std::optional<int> small_step_day;           // both flanges 0.45 mm thinner (< h) that day
  // From the reprofiling or the wheelset move on, each flange wears at its rate times these (a
  // new flange, another wheelset: its own rate).
  double left_rate_after = 1.0, right_rate_after = 1.0;
  std::optional<int> moved_day;  // the depot moved another wheelset in that day (recorded)
  // A flange wearing faster as it thins: each wheel's rate times exp(this x its wear in mm).
  double speedup_per_mm = 0.0;
};

// One axle's 90 days: depot days every 6th, 150-750 km on the others, 0.005 mm of noise per run.
std::vector<WheelHistory> axle_history(const Truth& truth, std::uint32_t seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> km_of_day(150.0, 750.0);
  std::normal_distribution<double> noise(0.0, 0.005);
  WheelHistory left{{"L01", 1, "left", 0}, {}, {}}, right{{"L01", 1, "right", 1}, {}, {}};
  double odometer = 0.0, wear_left = 3.0, wear_right = 2.0;
  double rate_left = truth.rate_left, rate_right = truth.rate_right;
  for (int day = 0; day < 90; ++day) {
    const double t = 20454.0 + day + 0.25;
    if (truth.reprofile_day && day == *truth.reprofile_day) wear_left = wear_right = 0.0;
    if ((truth.reprofile_day && day == *truth.reprofile_day) ||
        (truth.moved_day && day == *truth.moved_day)) {
      rate_left *= truth.left_rate_after;
      rate_right *= truth.right_rate_after;
    }
    if (truth.moved_day && day == *truth.moved_day) {
      for (WheelHistory* wheel : {&left, &right}) {
        wheel->maintenance.push_back({"", 20454.0 + day, odometer, "wheelset_moved"});
      }
    }
    if (truth.small_step_day && day == *truth.small_step_day) {
      wear_left -= 0.45;
      wear_right -= 0.45;
    }
    if (day % 6 == 5) continue;
    const double drift = truth.drift_from_day && day > *truth.drift_from_day
                             ? truth.drift_mm_per_day * (day - *truth.drift_from_day)
                             : 0.0;
    left.runs.push_back({day, "", t, odometer, 2.0 + wear_left + noise(random)});
    right.runs.push_back({day, "", t, odometer, 2.0 + wear_right + drift + noise(random)});
    const double km = km_of_day(random);
    odometer += km;
    wear_left += rate_left * std::exp(truth.speedup_per_mm * wear_left) * km / 1000.0;
    wear_right += rate_right * std::exp(truth.speedup_per_mm * wear_right) * km / 1000.0;
  }
  return {left, right};
}

const WheelWear& side(const FleetWear& fleet, const std::string& name) {
  return fleet.wheels[0].wheel.side == name ? fleet.wheels[0] : fleet.wheels[1];
}

TEST(FleetWear, RatesWithIntervalsThatHoldTheTruth) {
  const FleetWear fleet = estimate_fleet_wear(axle_history({}, 1), {});
  ASSERT_EQ(fleet.wheels.size(), 2u);
  for (const auto& [name, rate] : {std::pair{"left", 0.08}, {"right", 0.04}}) {
    const WheelWear& w = side(fleet, name);
    EXPECT_EQ(w.status, "ok") << name;
    EXPECT_NEAR(w.rate_mm_per_1000km, rate, 0.05 * rate) << name;
    EXPECT_LT(w.rate_low, rate) << name;
    EXPECT_GT(w.rate_high, rate) << name;
    EXPECT_TRUE(w.reprofilings.empty()) << name;
  }
}

// `axles` axles of axle_history, each on a locomotive of its own.
std::vector<WheelHistory> fleet_of_axles(int axles, std::uint32_t seed) {
  std::vector<WheelHistory> fleet;
  for (int a = 0; a < axles; ++a) {
    for (WheelHistory wheel : axle_history({}, seed + static_cast<std::uint32_t>(a))) {
      wheel.wheel.locomotive = "L" + std::to_string(10 + a);
      fleet.push_back(wheel);
    }
  }
  return fleet;
}

// Each wheel's own jackknife has B - 1 = 3 degrees of freedom on 90 days; the fleet's prior
// (moderated_spread.h) adds its own, and the intervals still hold at least as often as they say
// (300 wheels: a binomial standard error of 1.3 % at 95 % and 2.3 % at 80 %). On these purely
// independent errors they hold more often than that at 80 % (about 90 %): leaving a stretch of
// a trending history out takes part of the odometer's leverage with it, so the jackknife
// overstates the variance where no slow error is there to fill it (docs/fleet.md, step 5).
TEST(FleetWear, EachWheelsIntervalTakesDegreesOfFreedomFromTheFleet) {
  int held95 = 0, held80 = 0, wheels = 0;
  for (std::uint32_t f = 0; f < 25; ++f) {
    const FleetWear fleet = estimate_fleet_wear(fleet_of_axles(6, 100 + 10 * f), {});
    for (const WheelWear& w : fleet.wheels) {
      ASSERT_EQ(w.status, "ok");
      EXPECT_GT(w.rate_dof, 3);
      const double rate = w.wheel.side == "left" ? 0.08 : 0.04;
      const auto [low95, high95] = rate_interval(w, 0.95);
      const auto [low80, high80] = rate_interval(w, 0.80);
      held95 += low95 <= rate && rate <= high95 ? 1 : 0;
      held80 += low80 <= rate && rate <= high80 ? 1 : 0;
      ++wheels;
    }
  }
  EXPECT_GT(held95, 0.92 * wheels) << held95;
  EXPECT_LT(held95, 0.995 * wheels) << held95;
  EXPECT_GT(held80, 0.75 * wheels);
  EXPECT_LT(held80, 0.94 * wheels);
}

TEST(FleetWear, AReprofilingIsFoundFromTheJumpBack) {
  Truth truth;
  truth.reprofile_day = 47;
  const FleetWear fleet = estimate_fleet_wear(axle_history(truth, 2), {});
  for (const WheelWear& w : fleet.wheels) {
    ASSERT_EQ(w.reprofilings.size(), 1u);
    EXPECT_TRUE(w.reprofilings[0].found);
    EXPECT_FALSE(w.reprofilings[0].recorded);
    EXPECT_EQ(w.segment.back(), 1);
  }
  EXPECT_NEAR(side(fleet, "left").rate_mm_per_1000km, 0.08, 0.004);
}

TEST(FleetWear, ADriftingSensorIsAFaultNotWear) {
  Truth truth;
  truth.drift_from_day = 20;
  const FleetWear fleet = estimate_fleet_wear(axle_history(truth, 3), {});
  const WheelWear& right = side(fleet, "right");
  const WheelWear& left = side(fleet, "left");
  ASSERT_TRUE(right.sensor_fault.has_value());
  EXPECT_EQ(right.status, "sensor fault");
  EXPECT_NEAR(right.sensor_fault->rate_mm_per_day, 0.01, 0.002);
  EXPECT_NEAR(right.rate_mm_per_1000km, 0.04, 0.004);  // the drift fitted out
  EXPECT_FALSE(left.sensor_fault.has_value());
}

// A lathe pass or a wheelset moved in from another axle gives the axle new flanges, which wear
// at rates of their own (on the second fleet reality a thinner flange wears faster, so a new one
// slower): the bend from the change on is no drift (new_flange_rates.h), and a sensor that starts
// drifting a few runs after a lathe pass is still flagged.
TEST(FleetWear, ANewFlangesOwnRateIsNoDriftButADriftJustAfterALathePassIs) {
  Truth lathe;
  lathe.reprofile_day = 45;
  lathe.left_rate_after = 0.7;
  lathe.right_rate_after = 0.9;
  Truth moved;
  moved.moved_day = 45;
  moved.left_rate_after = 0.6;
  moved.right_rate_after = 1.1;
  for (const auto& [truth, name] : {std::pair{lathe, "reprofiled"}, {moved, "wheelset moved"}}) {
    for (const std::uint32_t seed : {11u, 12u, 13u}) {
      const FleetWear fleet = estimate_fleet_wear(axle_history(truth, seed), {});
      for (const WheelWear& w : fleet.wheels) {
        EXPECT_FALSE(w.sensor_fault.has_value()) << name << " seed " << seed << " " << w.wheel.side;
        EXPECT_EQ(w.status, "ok") << name << " seed " << seed << " " << w.wheel.side;
      }
    }
  }
  Truth drift = lathe;
  drift.drift_from_day = 48;
  for (const std::uint32_t seed : {11u, 12u, 13u}) {
    const FleetWear fleet = estimate_fleet_wear(axle_history(drift, seed), {});
    EXPECT_TRUE(side(fleet, "right").sensor_fault.has_value()) << "seed " << seed;
    EXPECT_FALSE(side(fleet, "left").sensor_fault.has_value()) << "seed " << seed;
  }
}

// A flange wearing faster as it thins (6 % faster per mm of wear) bends its clearance upward in
// km over the flange's life, which the drift's terms in days take for a drift where the km per
// day are steady (seed 22: the left sensor, at t > 6, without wear_change_in_km.h's comparison);
// a change in km fits it better than one in days. A drift on such an axle grows with days, depot
// days included, and is still flagged.
TEST(FleetWear, AFlangeWearingFasterAsItThinsIsNoDriftButADriftOnItIs) {
  Truth thinning;
  thinning.speedup_per_mm = 0.06;
  for (const std::uint32_t seed : {21u, 22u, 23u}) {
    const FleetWear fleet = estimate_fleet_wear(axle_history(thinning, seed), {});
    for (const WheelWear& w : fleet.wheels) {
      EXPECT_FALSE(w.sensor_fault.has_value()) << "seed " << seed << " " << w.wheel.side;
    }
  }
  Truth drift = thinning;
  drift.drift_from_day = 45;
  for (std::uint32_t seed = 21; seed <= 28; ++seed) {
    const FleetWear fleet = estimate_fleet_wear(axle_history(drift, seed), {});
    EXPECT_TRUE(side(fleet, "right").sensor_fault.has_value()) << "seed " << seed;
    EXPECT_FALSE(side(fleet, "left").sensor_fault.has_value()) << "seed " << seed;
  }
}

// A six-axle locomotive whose axles all wander alike (a slow wave of 0.3 mm in every right
// wheel's clearance, as a route whose curves wear one flange more for a spell would), with one sensor
// (axle 4 right) drifting from day 30 when `drifting`.
std::vector<WheelHistory> locomotive_history(bool drifting, std::uint32_t seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> km_of_day(150.0, 750.0);
  std::normal_distribution<double> noise(0.0, 0.005);
  std::vector<WheelHistory> wheels;
  for (int axle = 1; axle <= 6; ++axle) {
    wheels.push_back({{"L01", axle, "left", 2 * axle - 2}, {}, {}});
    wheels.push_back({{"L01", axle, "right", 2 * axle - 1}, {}, {}});
  }
  double odometer = 0.0;
  for (int day = 0; day < 90; ++day) {
    const double t = 20454.0 + day + 0.25;
    const double wave = 0.3 * std::sin(2.0 * M_PI * day / 60.0);
    if (day % 6 != 5) {
      for (std::size_t w = 0; w < wheels.size(); ++w) {
        const double rate = 0.04 + 0.005 * static_cast<double>(w);  // mm per 1000 km
        const bool drifts = drifting && w == 7 && day > 30;
        const double clearance = 3.0 + rate * odometer / 1000.0 + (w % 2 == 1 ? wave : 0.0) +
                                 (drifts ? 0.01 * (day - 30) : 0.0) + noise(random);
        wheels[w].runs.push_back({day, "", t, odometer, clearance});
      }
    }
    odometer += km_of_day(random);
  }
  return wheels;
}

TEST(FleetWear, AWanderAllAxlesShareIsNoDriftButOneSensorStandingOutIs) {
  for (const bool drifting : {false, true}) {
    const FleetWear fleet = estimate_fleet_wear(locomotive_history(drifting, 7), {});
    ASSERT_EQ(fleet.wheels.size(), 12u);
    for (const WheelWear& w : fleet.wheels) {
      const bool the_drifting_one = drifting && w.wheel.axle == 4 && w.wheel.side == "right";
      EXPECT_EQ(w.sensor_fault.has_value(), the_drifting_one)
          << "axle " << w.wheel.axle << " " << w.wheel.side << (drifting ? " (drift)" : "");
    }
  }
}

TEST(FleetWear, ARateBelowZeroIsAMissedReprofilingWhenAStepExplainsIt) {
  Truth truth;
  truth.rate_left = truth.rate_right = 0.002;  // a lathe pass of 0.45 mm outweighs the wear
  truth.small_step_day = 45;
  const FleetWear fleet = estimate_fleet_wear(axle_history(truth, 5), {});
  for (const WheelWear& w : fleet.wheels) {
    EXPECT_LT(w.line_rate_high, 0.0) << w.wheel.side;
    EXPECT_EQ(w.status, "missed reprofiling") << w.wheel.side;
  }
}

TEST(FleetWear, ARateBelowZeroIsASensorFaultWhenADriftExplainsIt) {
  Truth truth;
  truth.rate_right = 0.002;
  truth.drift_from_day = 0;
  truth.drift_mm_per_day = -0.02;
  // The right wheel alone (no partner to compare with): its own line falls with time.
  const FleetWear fleet = estimate_fleet_wear({axle_history(truth, 6)[1]}, {});
  ASSERT_EQ(fleet.wheels.size(), 1u);
  EXPECT_LT(fleet.wheels[0].rate_high, 0.0);
  EXPECT_EQ(fleet.wheels[0].status, "sensor fault");
}

// A lone wheel (no partner to hold a drift against) whose sensor drifts down from the first day
// about as fast as its flange wears (0.02 mm per 1000 km at 150-750 km on five days of six): it
// reads as a flange that does not wear, its rate's interval around zero. Beside a locomotive
// whose wheels wear at 0.04 and 0.08 that is no wear seen where wear should show; alone, its
// interval is all the fleet says.
TEST(FleetWear, ARateThatCannotBeToldFromNoWearBesideWheelsThatWearIsNeverOk) {
  Truth truth;
  truth.rate_right = 0.02;
  truth.drift_from_day = 0;
  truth.drift_mm_per_day = -0.0072;
  const WheelHistory lone = axle_history(truth, 6)[1];
  std::vector<WheelHistory> fleet_wheels = axle_history({}, 2);
  for (WheelHistory& wheel : fleet_wheels) wheel.wheel.locomotive = "L02";
  fleet_wheels.push_back(lone);
  const FleetWear fleet = estimate_fleet_wear(fleet_wheels, {});
  ASSERT_EQ(fleet.wheels.size(), 3u);
  for (const WheelWear& w : fleet.wheels) {
    if (w.wheel.locomotive == "L02") {
      EXPECT_EQ(w.status, "ok") << w.wheel.side;
      continue;
    }
    EXPECT_LE(w.rate_low, 0.0);
    EXPECT_GT(w.rate_high, 0.0);
    EXPECT_EQ(w.status, "sensor fault");
  }
  const FleetWear alone = estimate_fleet_wear({lone}, {});
  EXPECT_EQ(alone.wheels[0].status, "ok");
  // Its first six weeks: too short a history to call a slow flange's wear none.
  for (WheelHistory& wheel : fleet_wheels) {
    std::erase_if(wheel.runs, [](const WearObservation& run) { return run.day > 20454.0 + 42.0; });
  }
  const FleetWear short_history = estimate_fleet_wear(fleet_wheels, {});
  for (const WheelWear& w : short_history.wheels) {
    EXPECT_EQ(w.status, "ok") << w.wheel.locomotive << " " << w.wheel.side << ": rate "
                              << w.rate_mm_per_1000km << " [" << w.rate_low << ", " << w.rate_high
                              << "]";
  }
}

TEST(FleetWear, TheWarningForecastFollowsTheRate) {
  const FleetWear fleet = estimate_fleet_wear(axle_history({}, 4), {});
  const WheelWear& w = side(fleet, "left");
  ASSERT_TRUE(w.warning.km.has_value());
  // 8 mm warning clearance: what is left of it from the line's clearance now at the history's mean
  // rate.
  EXPECT_NEAR(*w.warning.km, (8.0 - w.clearance_now_mm) / (w.rate_mm_per_1000km / 1000.0), 1e-6);
  EXPECT_LT(*w.warning.km_low, *w.warning.km);
  EXPECT_GT(*w.warning.km_high, *w.warning.km);
  EXPECT_FALSE(w.warning.date.empty());
  EXPECT_EQ(fleet.wheels.front().wheel.side, "left");  // the sooner wheel first
}

TEST(LimitForecast, ARateBarelyAboveZeroGivesADateBeyondTheCalendar) {
  EXPECT_EQ(date_of_day(0.0), "1970-01-01");
  EXPECT_EQ(date_of_day(2932896.0), "9999-12-31");
  EXPECT_EQ(date_of_day(2932897.0), "after 9999-12-31");
  // 1 mm to go at 1e-15 mm/km and 100 km a day: 1e13 days.
  const LimitForecast f = forecast_limit({5.0, 1e-15, 1e-15, 1e-15, 100.0, 20000.0}, 6.0);
  ASSERT_TRUE(f.days);
  EXPECT_EQ(f.date, "after 9999-12-31");
}

}  // namespace
}  // namespace flange::host
