// SPDX-License-Identifier: MIT
// `flange wear`'s estimator: every wheel's history in, its wear rate, reprofilings, sensor fault
// and forecast out. Per axle: the two wheels' runs side by side; reprofilings found where the
// axle's clearance jumps back (reprofiling_search.h) or recorded by the depot start a new
// segment (so does a recorded sensor replacement or wheelset move, without being a
// reprofiling); a drift of one sensor away from its partner (sensor_drift.h) is a sensor fault and
// is fitted out of that wheel's series rather than read as wear; each wheel's line
// (wear_line_fit.h) gives its rate per 1000 km with a 95 % interval and the forecast of when its
// current flange reaches the warning and the critical clearance (limit_forecast.h), allowing
// wear that speeds up or slows as the flange thins when the fleet's wheels show it
// (wear_acceleration.h).
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "block_jackknife.h"
#include "history_mean_rate.h"
#include "limit_forecast.h"
#include "sensor_drift.h"
#include "sensor_flag_latch.h"
#include "sensor_sensitivity.h"
#include "thresholds.h"
#include "wear_acceleration.h"
#include "wear_line_fit.h"
#include "wheel_history.h"

namespace flange::host {

struct ReprofilingEvent {
  std::string last_run_before;  // the runs either side of it
  std::string first_run_after;
  double odometer_km = 0.0;  // at the first run after it
  bool found = false;        // the clearance jumped back by more than h
  bool recorded = false;     // the depot's maintenance record says so
  std::string recorded_at;   // the record's time when recorded
};

struct WheelWear {
  WheelId wheel;
  std::vector<WearObservation> runs;
  std::vector<int> segment;  // per run: which flange (0 before the first reprofiling, ...)
  std::vector<ReprofilingEvent> reprofilings;
  // "ok", "sensor fault", "missed reprofiling" (a rate wholly below zero that a step explains
  // better than a drift: negative_rate.h) or "too few runs"
  std::string status = "ok";
  std::optional<WearLineFit> fit;  // the straight line (the forecast's)
  // The history's mean wear per 1000 km (history_mean_rate.h; the line's slope when a drift is
  // fitted out or the history's pieces cannot be fitted), with its 95 % interval.
  double rate_mm_per_1000km = 0.0, rate_low = 0.0, rate_high = 0.0;
  // The rate's standard error (per 1000 km) allowing errors correlated from run to run, and
  // Student t's degrees of freedom for it (the jackknife, block_jackknife.h, moderated by the
  // fleet's, moderated_spread.h): an interval at any level.
  double rate_se = 0.0;
  int rate_dof = 0;
  // The straight line's slope's 95 % interval (the forecast's rate; per 1000 km).
  double line_rate_low = 0.0, line_rate_high = 0.0;
  SerialSpread own_spread;  // the line's own jackknife, before the moderation
  std::optional<HistoryMeanFit> history_mean;  // the rate's fit, with its own jackknife
  // What its line says about wear speeding up as the flange thins (wear_acceleration.h).
  AccelerationEvidence acceleration_evidence;
  double clearance_now_mm = 0.0;    // the fitted line at the last run (drift fitted out)
  double wear_now_mm = 0.0;         // clearance_now_mm - the sensor gap on a new flange
  LimitForecast warning, critical;  // 95 % intervals
  ForecastInput forecast_input;     // what they were made from: forecasts at other levels
  std::optional<DriftFinding> sensor_fault;  // this estimate's drift search
  // The flag kept from one estimate to the next (sensor_flag_latch.h): pending, or latched
  // until the depot acts; set by latch_sensor_flags (fleet_sensor_flags.h).
  std::optional<SensorFlag> sensor_flag;
  double km_per_day = 0.0;  // the locomotive's, over this wheel's history
};

struct FleetWear {
  ThresholdConfig thresholds;
  double warning_clearance_mm = 0.0;
  double critical_clearance_mm = 0.0;
  std::vector<WheelWear> wheels;  // by days to the warning clearance, soonest first
  // b pooled over the wheels whose line is wear alone; the forecasts use it weighed by how well
  // it is known (acceleration_in_dates), and its calendar trend as the season to come.
  FleetAcceleration acceleration;
};

// `sensitivity`: the sensors' slope (mm/V) by clearance, from the calibration they ran with;
// without it a drift is fitted in mm (a constant slope).
FleetWear estimate_fleet_wear(const std::vector<WheelHistory>& histories,
                              const ThresholdConfig& thresholds,
                              const SensitivityAt& sensitivity = {});

// The rate's interval at `level` (0 < level < 1), per 1000 km: {low, high}.
std::pair<double, double> rate_interval(const WheelWear& wheel, double level);

// Days to the warning clearance for sorting: 0 when reached, +inf when unknown.
double days_to_warning(const WheelWear& wheel);

}  // namespace flange::host
