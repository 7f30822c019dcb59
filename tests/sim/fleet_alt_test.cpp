// SPDX-License-Identifier: MIT
// The second fleet reality (sim/fleet_alt/): its laws do what its README says (curves of either
// hand shift the wheelset, hunting on tangents, the sensor's response to clearance, temperature
// and drift, wear faster as the flange thins), the depot's events happen on depot days and do
// what they say, and the folder it writes is what the service path reads.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "fleet_alt_folder.h"
#include "fleet_alt_limits.h"
#include "fleet_alt_plan.h"
#include "fleet_alt_recording.h"
#include "fleet_alt_sensor.h"
#include "fleet_alt_track.h"
#include "fleet_truth_file.h"
#include "locomotive_manifest.h"
#include "test_files.h"

namespace flange::fleet_alt {
namespace {

namespace fs = std::filesystem;

FleetAltSettings small_settings() {
  FleetAltSettings settings;
  settings.locomotives = 3;
  settings.days = 60;
  settings.seed = 5;
  settings.recording_s = 60.0;
  return settings;
}

TEST(FleetAltSensor, OpensWithClearanceDropsWithHeatAndDrifts) {
  SensorUnit unit;
  EXPECT_GT(sensor_voltage(unit, 6.0, 20.0, 0.0), sensor_voltage(unit, 2.0, 20.0, 0.0) + 3.0);
  EXPECT_LT(sensor_voltage(unit, 6.0, 50.0, 0.0), sensor_voltage(unit, 6.0, 20.0, 0.0));
  unit.drift_v_per_day = -0.02;
  unit.drift_start_day = 10;
  EXPECT_DOUBLE_EQ(sensor_voltage(unit, 6.0, 20.0, 10.0),
                   sensor_voltage(SensorUnit{}, 6.0, 20.0, 0));
  EXPECT_NEAR(sensor_voltage(unit, 6.0, 20.0, 30.0) - sensor_voltage(SensorUnit{}, 6.0, 20.0, 0),
              -0.4, 1e-12);
  EXPECT_EQ(recorded_voltage(12.0), kOutputHighV);
}

TEST(FleetAltTrack, CurvesOfEitherHandShiftTheWheelsetAndTangentsHunt) {
  FleetRandom random(3, 1);
  const RouteTrack track = draw_route_track(route_kinds().at(1), random);  // escarpment
  ASSERT_GT(track.curves.size(), 10u);
  int right = 0, left = 0;
  for (const CurveStretch& curve : track.curves) {
    const double middle = curve.start_m + 0.5 * curve.length_m;
    const double y = lateral_shift_mm(track, 1, middle, 1.0, 0.0, 0.0);
    if (curve.curvature_per_m > 0.0) {
      EXPECT_GT(y, 0.2) << "a right-hand curve closes the left clearance";
      ++right;
    } else {
      EXPECT_LT(y, -0.2) << "a left-hand curve closes the right clearance";
      ++left;
    }
  }
  EXPECT_GT(right, 0);
  EXPECT_GT(left, 0);
  // On a plain route's tangent at 24 m/s the wheelset hunts about the alignment.
  FleetRandom plain_random(3, 2);
  const RouteTrack plain = draw_route_track(route_kinds().at(0), plain_random);
  const double tangent = plain.curves.at(0).start_m - 200.0;
  double swing = 0.0;
  for (double s = tangent; s < tangent + 20.0; s += 0.5) {
    const double y = lateral_shift_mm(plain, 2, s, 2.0, 0.0, 0.0) - 0.7 * alignment_mm(plain, s);
    swing = std::max(swing, std::abs(y));
  }
  EXPECT_GT(swing, 0.15);
}

TEST(FleetAltPlan, TheSameSeedGivesTheSameFleet) {
  const FleetAltTruth a = plan_fleet_alt(small_settings());
  const FleetAltTruth b = plan_fleet_alt(small_settings());
  FleetAltSettings other = small_settings();
  other.seed = 6;
  const FleetAltTruth c = plan_fleet_alt(other);
  EXPECT_EQ(a.locomotives[0].days[30].wheels[3].wear_mm,
            b.locomotives[0].days[30].wheels[3].wear_mm);
  EXPECT_NE(a.locomotives[0].days[30].wheels[3].wear_mm,
            c.locomotives[0].days[30].wheels[3].wear_mm);
}

TEST(FleetAltPlan, TheDepotsEventsHappenOnDepotDaysAndDoWhatTheySay) {
  const FleetAltTruth truth = plan_fleet_alt(small_settings());
  int resets = 0, replaced = 0, moved = 0, reprofiled = 0;
  for (const DepotEvent& event : truth.events) {
    const LocomotiveHistory& loco =
        truth.locomotives.at(static_cast<std::size_t>(event.locomotive));
    const LocomotiveDay& day = loco.days.at(static_cast<std::size_t>(event.day));
    EXPECT_EQ(day.km, 0.0) << "an event on a running day";
    const LocomotiveDay& before = loco.days.at(static_cast<std::size_t>(event.day - 1));
    if (event.kind == DepotEventKind::kOdometerReset) {
      ++resets;
      EXPECT_GT(event.odometer_reading_km, 1000.0);
      EXPECT_EQ(day.odometer_reading_km, 0.0);
    }
    if (event.kind == DepotEventKind::kSensorReplaced) {
      ++replaced;
      const int c = 2 * (event.axle - 1) + event.side;
      EXPECT_NE(day.wheels[c].serial, before.wheels[c].serial);
      EXPECT_EQ(day.wheels[c].serial, event.sensor_serial);
    }
    if (event.kind == DepotEventKind::kWheelsetMoved) {
      ++moved;
      const int c = 2 * (event.axle - 1), from = 2 * (event.from_axle - 1);
      const double gained = loco.positions[from].accrued_mm[event.day - 1];
      EXPECT_NEAR(day.wheels[c].wear_mm, before.wheels[from].wear_mm + gained, 1e-12);
    }
    if (event.kind == DepotEventKind::kReprofile) {
      ++reprofiled;
      EXPECT_LE(day.wheels[2 * (event.axle - 1)].wear_mm, 0.15);
      EXPECT_LE(day.wheels[2 * (event.axle - 1) + 1].wear_mm, 0.15);
    }
  }
  EXPECT_EQ(resets, 1);
  EXPECT_EQ(replaced, 1);
  EXPECT_EQ(moved, 2);  // the two axles' wheelsets change places
  EXPECT_GT(reprofiled, 0);
}

TEST(FleetAltPlan, AThinnerFlangeWearsFaster) {
  FleetAltSettings settings = small_settings();
  settings.days = 200;
  const FleetAltTruth truth = plan_fleet_alt(settings);
  // Every wheel's accrued wear per km of its base rate, early (thick) against late (thin) in a
  // flange's life, on the same route and season: pooled over the fleet the thin one is higher.
  double thick = 0.0, thin = 0.0;
  int thick_n = 0, thin_n = 0;
  for (const LocomotiveHistory& loco : truth.locomotives) {
    for (int c = 0; c < kWheels; ++c) {
      for (std::size_t d = 0; d < loco.days.size(); ++d) {
        if (loco.days[d].km == 0.0) continue;
        const double per_km =
            loco.positions[c].accrued_mm[d] / loco.days[d].km / loco.positions[c].base_rate[d];
        (loco.days[d].wheels[c].wear_mm < 1.5 ? thick : thin) += per_km;
        ++(loco.days[d].wheels[c].wear_mm < 1.5 ? thick_n : thin_n);
      }
    }
  }
  ASSERT_GT(thick_n, 0);
  ASSERT_GT(thin_n, 0);
  EXPECT_GT(thin / thin_n, thick / thick_n);
}

// Every position's flange gets its limit dates: after the locomotive's last recorded day (the
// flanges are under the lathe's 4.6 mm, short of the warning's 6 mm of wear), the critical one
// after the warning one, and within the ten years for all but the slowest.
TEST(FleetAltLimits, EveryFlangeReachesItsLimitsAfterThePeriod) {
  const FleetAltTruth truth = plan_fleet_alt(small_settings());
  int dated = 0, wheels = 0;
  for (const LocomotiveHistory& loco : truth.locomotives) {
    const int last = last_recorded_day(loco);
    ASSERT_GT(last, 40);
    EXPECT_EQ(static_cast<int>(loco.days.size() + loco.days_after.size()), kTruthHorizonDays);
    for (const PositionTruth& position : loco.positions) {
      ++wheels;
      if (!position.warning_day || !position.critical_day) continue;
      ++dated;
      EXPECT_GT(*position.warning_day, last);
      EXPECT_GT(*position.critical_day, *position.warning_day);
      EXPECT_LT(*position.critical_day, kTruthHorizonDays);
    }
  }
  EXPECT_GE(dated, wheels - 2);
}

// Whether the flange at position c from the start of day `from` to that of `to` is one: its wear
// grew by what it gained (no lathe pass or wheelset move in between).
bool unchanged_flange(const LocomotiveHistory& loco, int c, int from, int to) {
  double gained = 0.0;
  for (int d = from; d < to; ++d) gained += loco.positions[c].accrued_mm[d];
  return std::abs(loco.days[from].wheels[c].wear_mm + gained - loco.days[to].wheels[c].wear_mm) <
         1e-12;
}

// A limit reached inside the period lands on the day the recorded wear passes it: the walk is
// the wear law the period's days were worn by (the same sums, so the tolerance is rounding's).
TEST(FleetAltLimits, ALimitInsideThePeriodFallsOnTheDayTheRecordedWearPassesIt) {
  const FleetAltTruth truth = plan_fleet_alt(small_settings());
  int checked = 0;
  for (int l = 0; l < static_cast<int>(truth.locomotives.size()); ++l) {
    const LocomotiveHistory& loco = truth.locomotives[static_cast<std::size_t>(l)];
    for (int c = 0; c < kWheels; ++c) {
      // From day 1 to day 40, on a position whose flange was neither turned nor moved.
      if (!unchanged_flange(loco, c, 1, 40)) continue;
      int day = 39;
      while (day > 1 && loco.days[day].km == 0.0) --day;  // the last day that wore it before 40
      const double limit = loco.days[40].wheels[c].wear_mm - 1e-9;
      EXPECT_EQ(limit_day(truth, l, c, 1, limit), day) << loco.name << " channel " << c;
      ++checked;
    }
  }
  EXPECT_GT(checked, 10);
}

// After the period the km to a date agree with the wear law integrated in closed form: with
// dw/dx = r exp(0.06 w), x = (exp(-0.06 w0) - exp(-0.06 w1)) / (0.06 r). The route and the
// season make r vary from day to day, so the km lie between the integral at the largest and at
// the smallest r of the days walked (a bracket the law itself gives, not a fitted tolerance),
// and the day before the date falls short of the km at the largest r.
TEST(FleetAltLimits, TheKmToADateAgreeWithTheWearLawIntegrated) {
  const FleetAltTruth truth = plan_fleet_alt(small_settings());
  const double limit = kCriticalClearanceMm - kNewFlangeClearanceMm;
  int checked = 0;
  for (const LocomotiveHistory& loco : truth.locomotives) {
    const auto from = static_cast<std::size_t>(last_recorded_day(loco));
    for (int c = 0; c < kWheels; ++c) {
      const PositionTruth& position = loco.positions[static_cast<std::size_t>(c)];
      if (!position.critical_day) continue;
      const int axle = c / 2 + 1, side = c % 2;
      const double base = position.base_rate[from];
      double km = 0.0, km_before = 0.0, r_low = 1e9, r_high = 0.0;
      for (auto d = from; d <= static_cast<std::size_t>(*position.critical_day); ++d) {
        const bool after = d >= loco.days.size();
        const int route = after ? loco.days_after[d - loco.days.size()].route : loco.days[d].route;
        const double day_km = after ? loco.days_after[d - loco.days.size()].km : loco.days[d].km;
        const double ambient =
            after ? truth.ambient_after_c[d - loco.days.size()] : truth.ambient_c[d];
        km_before = km;
        km += day_km;
        if (day_km == 0.0) continue;
        const double r =
            wear_rate_mm_per_1000km(truth.routes[route].kind, axle, side, base, 0.0, ambient) /
            1000.0;
        r_low = std::min(r_low, r);
        r_high = std::max(r_high, r);
      }
      const double w0 = loco.days[from].wheels[c].wear_mm;
      const double integral = std::exp(-0.06 * w0) - std::exp(-0.06 * limit);
      EXPECT_GE(km, integral / (0.06 * r_high)) << loco.name << " channel " << c;
      EXPECT_LT(km_before, integral / (0.06 * r_low)) << loco.name << " channel " << c;
      ++checked;
    }
  }
  EXPECT_GT(checked, 20);
}

TEST(FleetAltPlan, RefusesSettingsOutOfRange) {
  FleetAltSettings settings = small_settings();
  settings.days = 5;
  EXPECT_THROW(plan_fleet_alt(settings), std::invalid_argument);
  settings = small_settings();
  settings.locomotives = 0;
  EXPECT_THROW(plan_fleet_alt(settings), std::invalid_argument);
}

// The folder: manifests the service path loads, runs.csv in time order with odometers that only
// fall at the recorded reset, and a truth file `flange wear --truth` reads.
TEST(FleetAltFolder, WritesWhatTheServicePathReads) {
  const fs::path dir = testing::fresh_test_dir("fleet_alt_folder");
  const FleetAltTruth truth = plan_fleet_alt(small_settings());
  const FleetAltWritten written = write_fleet_alt_folder(truth, dir, "test");
  std::ifstream runs(dir / "runs.csv");
  std::string line;
  std::getline(runs, line);
  EXPECT_EQ(line, "started_at,locomotive,manifest,distance_km,odometer_km");
  int lines = 0, drops = 0;
  std::map<std::string, double> last_odometer;
  while (std::getline(runs, line)) {
    std::stringstream fields(line);
    std::string started, loco, manifest, distance, odometer;
    std::getline(fields, started, ',');
    std::getline(fields, loco, ',');
    std::getline(fields, manifest, ',');
    std::getline(fields, distance, ',');
    std::getline(fields, odometer, ',');
    if (lines++ < 3) {
      EXPECT_EQ(host::load_locomotive_manifest((dir / manifest).string()).channels.size(), 12u);
    }
    const double km = std::stod(odometer);
    if (last_odometer.count(loco) != 0 && km < last_odometer[loco]) ++drops;
    last_odometer[loco] = km;
  }
  EXPECT_EQ(lines, written.runs);
  EXPECT_EQ(drops, 1) << "the odometer falls once: at its reset";
  const sim::FleetTruth read = sim::read_fleet_truth(dir / "fleet_truth.json");
  EXPECT_EQ(read.locomotives.size(), 3u);
  EXPECT_EQ(read.drifts.size(), 1u);
  for (const sim::WheelTruth& wheel : read.locomotives[0].wheels) {
    EXPECT_GT(wheel.wear_rate_mm_per_1000km, 0.0);
  }
  // The limit dates, for the limits the estimate's defaults mean, as `flange wear --truth` reads
  // them.
  ASSERT_TRUE(read.limit_dates.has_value());
  EXPECT_EQ(read.limit_dates->warning_clearance_mm, 8.0);
  EXPECT_EQ(read.limit_dates->critical_clearance_mm, 10.0);
  EXPECT_EQ(read.limit_dates->horizon_days, kTruthHorizonDays);
  for (std::size_t l = 0; l < truth.locomotives.size(); ++l) {
    for (int c = 0; c < kWheels; ++c) {
      EXPECT_EQ(read.locomotives[l].wheels[c].warning_day,
                truth.locomotives[l].positions[c].warning_day);
      EXPECT_EQ(read.locomotives[l].wheels[c].critical_day,
                truth.locomotives[l].positions[c].critical_day);
    }
  }
  EXPECT_TRUE(fs::exists(dir / "bench" / "bench_3.csv"));
  EXPECT_TRUE(fs::exists(dir / "maintenance.csv"));
}

}  // namespace
}  // namespace flange::fleet_alt
