// SPDX-License-Identifier: MIT
// The reprofiling plan: each wheel's date the chosen risk's quantile of its forecast critical date
// (its rate's quantile alone without a forecast input), the wheels due before the horizon soonest
// first, the bad requests refused, and the risk kept: over many wheels with known rates and
// random daily km, the share that reach the critical clearance before their date is the risk
// asked for. On a fleet whose wear speeds up as the flange thins, and on one that wears
// linearly, the date is the dates' forecast's quantile (at risk 1/2 the critical date).
#include "reprofiling_plan.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <optional>
#include <random>
#include <stdexcept>

#include "host/synthetic_accelerating_fleet.h"
#include "input_error.h"
#include "limit_forecast.h"
#include "wear_line_fit.h"

namespace flange::host {
namespace {

constexpr double kLastDay = 20500.25;  // 2026-02-16T06:00Z

// A wheel as the estimator leaves it: `gap_mm` short of the 12 mm critical clearance, rate 0.1
// mm/1000 km with the 95 % interval [0.08, 0.12], 100 km a day.
WheelWear wheel(const std::string& loco, double gap_mm, double rate = 0.1, double half = 0.02) {
  WheelWear w;
  w.wheel = {loco, 1, "left", 0};
  w.runs.push_back({1, "2026-02-16T06:00:00Z", kLastDay, 50000.0, 12.0 - gap_mm});
  WearLineFit fit;
  fit.dof = 100000;  // the t quantiles are the normal ones
  fit.rate_mm_per_km = rate / 1000.0;
  w.fit = fit;
  w.rate_mm_per_1000km = rate;
  w.rate_low = rate - half;
  w.rate_high = rate + half;
  w.clearance_now_mm = 12.0 - gap_mm;
  w.km_per_day = 100.0;
  return w;
}

FleetWear fleet_of(std::vector<WheelWear> wheels) {
  FleetWear fleet;
  fleet.critical_clearance_mm = 12.0;
  fleet.wheels = std::move(wheels);
  return fleet;
}

TEST(ReprofilingPlan, TheRateAtRiskIsTheStatedIntervalsQuantile) {
  const WheelWear w = wheel("A", 2.0);
  EXPECT_NEAR(rate_at_risk(w, 0.025), 0.12, 1e-6);  // the interval's upper end
  EXPECT_NEAR(rate_at_risk(w, 0.975), 0.08, 1e-6);  // its lower end
  EXPECT_NEAR(rate_at_risk(w, 0.5), 0.1, 1e-12);
  // 5 %: 1.645 of the 1.960 standard errors the 95 % half-width stands for.
  EXPECT_NEAR(rate_at_risk(w, 0.05), 0.1 + 0.02 * 1.6449 / 1.9600, 1e-4);
  WheelWear lopsided = w;  // an interval wider above than below
  lopsided.rate_high = 0.16;
  EXPECT_NEAR(rate_at_risk(lopsided, 0.025), 0.16, 1e-6);
  EXPECT_NEAR(rate_at_risk(lopsided, 0.975), 0.08, 1e-6);
}

TEST(ReprofilingPlan, DueDatesFromTheRateAtRiskSoonestFirst) {
  // 2 mm at 0.12 mm/1000 km: 16,667 km, 166.7 days; 1 mm: 83.3 days; 3 mm: 250 days.
  const FleetWear fleet = fleet_of({wheel("far", 3.0), wheel("near", 1.0), wheel("mid", 2.0)});
  const ReprofilingPlan plan = plan_reprofiling(fleet, {"2026-10-01", 0.025});
  ASSERT_EQ(plan.wheels.size(), 2u);  // 2026-10-01 is day 20727: 226.75 days after the last run
  EXPECT_EQ(plan.wheels[0].wheel.locomotive, "near");
  EXPECT_NEAR(plan.wheels[0].due_day, kLastDay + 1000.0 / 0.12 / 100.0, 1e-6);
  EXPECT_EQ(plan.wheels[0].due_date, date_of_day(kLastDay + 83.33));
  EXPECT_EQ(plan.wheels[1].wheel.locomotive, "mid");
  EXPECT_NEAR(plan.wheels[1].due_day, kLastDay + 2000.0 / 0.12 / 100.0, 1e-6);
  EXPECT_EQ(plan.last_run_at, "2026-02-16T06:00:00Z");
  const std::string csv = plan_csv(plan);
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "locomotive,axle,side,due_date,status,wear_now_mm,rate_mm_per_1000km,"
            "rate_at_risk_mm_per_1000km,critical_date_at_rate");
  EXPECT_NE(csv.find("\nnear,1,left," + plan.wheels[0].due_date + ",ok,"), std::string::npos);
  // A lower risk brings the dates forward: the far wheel is due after 250 days at 0.12 mm/1000
  // km (2026-10-24), after 300 at the fitted rate (2026-12-13).
  EXPECT_EQ(plan_reprofiling(fleet, {"2026-11-01", 0.025}).wheels.size(), 3u);
  EXPECT_EQ(plan_reprofiling(fleet, {"2026-11-01", 0.5}).wheels.size(), 2u);
  EXPECT_EQ(plan_reprofiling(fleet, {"2027-01-01", 0.5}).wheels.size(), 3u);
  EXPECT_EQ(plan_reprofiling(fleet, {"2026-10-01", 0.9}).wheels.size(), 1u);
}

TEST(ReprofilingPlan, AWheelAtTheLimitIsDueNowOneWithoutAForecastIsNotPlanned) {
  WheelWear reached = wheel("reached", -0.5);
  WheelWear shrinking = wheel("shrinking", 2.0, -0.05, 0.01);  // never at any risk asked
  WheelWear unknown = wheel("unknown", 2.0);
  unknown.fit.reset();
  unknown.status = "too few runs";
  const ReprofilingPlan plan =
      plan_reprofiling(fleet_of({shrinking, unknown, reached}), {"2026-02-17", 0.05});
  ASSERT_EQ(plan.wheels.size(), 1u);
  EXPECT_EQ(plan.wheels[0].wheel.locomotive, "reached");
  EXPECT_TRUE(plan.wheels[0].reached);
  EXPECT_EQ(plan.wheels[0].due_date, "2026-02-16");
  ASSERT_EQ(plan.unplanned.size(), 1u);
  EXPECT_EQ(plan.unplanned[0].wheel.locomotive, "unknown");
  EXPECT_NE(plan_html_section(plan).find("unknown axle 1 left"), std::string::npos);
}

TEST(ReprofilingPlan, BadRequestsAreRefusedWithTheirRange) {
  const FleetWear fleet = fleet_of({wheel("A", 2.0)});
  const auto message = [&](const PlanRequest& request) {
    try {
      plan_reprofiling(fleet, request);
    } catch (const InputError& error) {
      return std::string(error.what());
    }
    return std::string("accepted");
  };
  for (const double risk : {0.0, 1.0, -0.1, 1.5, std::nan("")}) {
    EXPECT_NE(message({"2026-10-01", risk}).find("--risk"), std::string::npos) << risk;
  }
  EXPECT_EQ(message({"2026-10-01", 1e-9}), "accepted");
  EXPECT_NE(message({"2026-02-16", 0.05}).find("is not after the store's last run"),
            std::string::npos);
  EXPECT_NE(message({"2025-12-31", 0.05}).find("a date YYYY-MM-DD after 2026-02-16"),
            std::string::npos);
  for (const char* date : {"2026-13-01", "2026-02-30", "next week", "2026-10-01T00:00Z", ""}) {
    EXPECT_NE(message({date, 0.05}).find("is not a date"), std::string::npos) << date;
  }
}

// The plan's date as it was made before the fleet's acceleration reached it: the reported rate's
// quantile and the fitted clearance on the straight line.
double straight_line_due_day(const WheelWear& w, double critical_clearance_mm, double risk) {
  PlanInput input = plan_input(w);
  input.forecast.reset();
  const double t = t_one_sided(1.0 - risk, input.dof);
  const double half =
      t >= 0.0 ? w.rate_high - w.rate_mm_per_1000km : w.rate_mm_per_1000km - w.rate_low;
  const double rate = w.rate_mm_per_1000km + t * half / t95(input.dof);
  EXPECT_EQ(rate, rate_at_risk(input, risk));
  ForecastInput straight;
  straight.clearance_now_mm = w.clearance_now_mm;
  straight.rate_mm_per_km = straight.rate_low_mm_per_km = straight.rate_high_mm_per_km =
      rate / 1000.0;
  straight.km_per_day = w.km_per_day;
  straight.last_day = w.runs.back().day;
  const LimitForecast at_risk = forecast_limit(straight, critical_clearance_mm);
  return at_risk.days ? straight.last_day + *at_risk.days : NAN;
}

const WheelWear& estimated(const FleetWear& fleet, const WheelId& wheel) {
  for (const WheelWear& e : fleet.wheels) {
    if (e.wheel == wheel) return e;
  }
  throw std::logic_error("no such wheel");
}

// Wear per km r exp(0.06 wear): the dates bend, and so does the plan. At risk 1/2 each wheel's
// date is its critical date (the forecast's median), never after it; the straight line's date at
// the rate's quantile falls after the critical date on most wheels.
TEST(ReprofilingPlan, OnAnAcceleratingFleetTheDateAtEvenRiskIsTheCriticalDate) {
  for (const std::uint32_t seed : {1u, 2u, 3u}) {
    const FleetWear fleet =
        estimate_fleet_wear(testing::synthetic_accelerating_fleet(0.06, seed).histories, {});
    ASSERT_TRUE(fleet.acceleration.significant) << "seed " << seed;
    const ReprofilingPlan plan = plan_reprofiling(fleet, {"2200-01-01", 0.5});
    ASSERT_GE(plan.wheels.size(), 50u) << "seed " << seed;
    int bent = 0, straight_after_critical = 0;
    for (const PlannedWheel& w : plan.wheels) {
      const WheelWear& e = estimated(fleet, w.wheel);
      if (w.reached) continue;
      ASSERT_TRUE(e.critical.days.has_value());
      const double critical_day = e.runs.back().day + *e.critical.days;
      EXPECT_NEAR(w.due_day, critical_day, 1e-6) << "seed " << seed;
      EXPECT_LE(w.due_date, e.critical.date) << "seed " << seed;
      if (e.forecast_input.acceleration_per_mm == 0.0) continue;
      ++bent;
      if (straight_line_due_day(e, fleet.critical_clearance_mm, 0.5) > critical_day + 1.0) {
        ++straight_after_critical;
      }
    }
    EXPECT_GE(bent, 50) << "seed " << seed;
    EXPECT_GT(straight_after_critical, bent / 2) << "seed " << seed;
  }
}

// The due day at risk P is the P quantile of the dates' forecast of the critical date: the lower
// bound of its interval at the two-sided level 1 - 2P under 1/2, the upper at 2P - 1 above; at
// 1/2 the critical date, and there (only) the rate's quantile alone gives about the same day on
// a fleet that wears linearly (within 1 % of the days to come: its b within 0 and its season are
// in the date, weighed down; wear_acceleration.h). On the accelerating fleet (b = 0.06) and the
// linear one (b = 0).
TEST(ReprofilingPlan, TheDueDayAtRiskIsTheForecastsCriticalDateQuantile) {
  for (const double acceleration : {0.06, 0.0}) {
    const FleetWear fleet =
        estimate_fleet_wear(testing::synthetic_accelerating_fleet(acceleration, 1).histories, {});
    ASSERT_EQ(fleet.acceleration.significant, acceleration > 0.0);
    for (const double risk : {0.01, 0.05, 0.2, 0.5, 0.8}) {
      const ReprofilingPlan plan = plan_reprofiling(fleet, {"2200-01-01", risk});
      ASSERT_GE(plan.wheels.size(), 50u);
      int sooner_than_rate_alone = 0;
      for (const PlannedWheel& w : plan.wheels) {
        const WheelWear& e = estimated(fleet, w.wheel);
        ASSERT_GT(e.forecast_input.dof, 0);
        EXPECT_FALSE(w.on_rate_alone);
        const LimitForecast bounds =
            forecast_limit(e.forecast_input, fleet.critical_clearance_mm, std::abs(1 - 2 * risk));
        const std::optional<double> days = risk < 0.5    ? bounds.days_low
                                           : risk > 0.5 ? bounds.days_high
                                                        : e.critical.days;
        ASSERT_TRUE(days.has_value());
        EXPECT_EQ(w.due_day, e.forecast_input.last_day + *days) << "b " << acceleration;
        const double rate_alone = straight_line_due_day(e, fleet.critical_clearance_mm, risk);
        if (risk == 0.5 && acceleration == 0.0) {
          EXPECT_NEAR(w.due_day, rate_alone, 0.01 * (rate_alone - e.forecast_input.last_day));
        }
        sooner_than_rate_alone += w.due_day < rate_alone - 1.0;
      }
      // Under 1/2 the km per day's uncertainty moves most dates sooner than the rate's alone.
      if (risk < 0.5 && acceleration == 0.0) {
        EXPECT_GT(sooner_than_rate_alone, static_cast<int>(plan.wheels.size()) / 2) << risk;
      }
    }
  }
}

// The day a wheel at `clearance_mm` on `day` reaches the critical clearance wearing `rate` mm per
// 1000 km over the locomotive's days to come, each of uniform(150, 750) km as its history's.
double true_critical_day(double rate, double clearance_mm, double day, double critical_mm,
                         std::mt19937 future) {
  std::uniform_real_distribution<double> km_of_day(150.0, 750.0);
  for (;;) {
    const double next = clearance_mm + rate * km_of_day(future) / 1000.0;
    if (next >= critical_mm) return day + (critical_mm - clearance_mm) / (next - clearance_mm);
    clearance_mm = next;
    day += 1.0;
  }
}

// The days to come of a locomotive: the same at every risk.
std::mt19937 future_of(const std::string& locomotive) {
  std::seed_seq seed(locomotive.begin(), locomotive.end());
  return std::mt19937(seed);
}

// Wheels with known rates through the estimator (white noise, as its interval assumes) on
// locomotives whose km per day are random: the share whose true critical day, over their own
// days to come, is before the plan's is the risk.
TEST(ReprofilingPlan, TheRiskAskedForIsTheShareThatReachTheLimitFirst) {
  std::mt19937 random(20260216);
  std::uniform_real_distribution<double> rate_of(0.04, 0.1), km_of_day(150.0, 750.0);
  std::normal_distribution<double> noise(0.0, 0.05);
  std::vector<WheelHistory> histories;
  std::map<std::string, std::pair<double, double>> truth;  // rate, clearance at the last run
  for (int loco = 0; loco < 400; ++loco) {
    WheelHistory h{{fmt::format("L{:03d}", loco), 1, loco % 2 ? "right" : "left", 0}, {}, {}};
    const double rate = rate_of(random);
    double odometer = 0.0, clearance = 4.0;
    for (int day = 0; day < 60; ++day) {
      h.runs.push_back(
          {day, "2026-01-01T06:00:00Z", 20454.25 + day, odometer, clearance + noise(random)});
      const double km = km_of_day(random);
      odometer += km;
      clearance += rate * km / 1000.0;
    }
    truth[h.wheel.locomotive] = {
        rate, clearance - rate * (odometer - h.runs.back().odometer_km) / 1000.0};
    histories.push_back(std::move(h));
  }
  const FleetWear fleet = estimate_fleet_wear(histories, {});
  for (const double risk : {0.1, 0.3}) {
    const ReprofilingPlan plan = plan_reprofiling(fleet, {"2200-01-01", risk});
    ASSERT_EQ(plan.wheels.size(), 400u);
    int first = 0;
    for (const PlannedWheel& w : plan.wheels) {
      const auto& [rate, clearance_now] = truth.at(w.wheel.locomotive);
      const double last_day = estimated(fleet, w.wheel).runs.back().day;
      if (true_critical_day(rate, clearance_now, last_day, fleet.critical_clearance_mm,
                            future_of(w.wheel.locomotive)) < w.due_day) {
        ++first;
      }
    }
    // Binomial(400, risk): within 3.5 standard deviations.
    const double sd = std::sqrt(400.0 * risk * (1.0 - risk));
    EXPECT_NEAR(first, 400.0 * risk, 3.5 * sd) << "risk " << risk;
  }
}

}  // namespace
}  // namespace flange::host
