// SPDX-License-Identifier: MIT
#include "stored_wear_estimates.h"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "forecast_input_json.h"
#include "store.h"

namespace flange::cli {

namespace {

host::WheelEstimateRecord estimate_record(const host::WheelWear& wheel) {
  host::WheelEstimateRecord e;
  e.wheel = {wheel.wheel.locomotive, wheel.wheel.axle, wheel.wheel.side};
  e.channel = wheel.wheel.channel;
  e.status = wheel.status;
  const host::PlanInput plan = host::plan_input(wheel);
  e.has_fit = wheel.fit.has_value();
  for (std::size_t i = 0; i < wheel.runs.size() && i < wheel.segment.size(); ++i) {
    if (wheel.segment[i] == wheel.segment.back()) {
      e.segment_start = wheel.runs[i].at;
      break;
    }
  }
  e.last_run_at = plan.last_at;
  e.last_run_day = plan.last_day;
  e.rate_mm_per_1000km = wheel.rate_mm_per_1000km;
  e.rate_low = wheel.rate_low;
  e.rate_high = wheel.rate_high;
  e.rate_se = wheel.rate_se;
  e.rate_dof = wheel.rate_dof;
  e.fit_dof = wheel.fit ? wheel.fit->dof : 0;
  e.clearance_now_mm = wheel.clearance_now_mm;
  e.wear_now_mm = wheel.wear_now_mm;
  e.km_per_day = wheel.km_per_day;
  const host::ForecastInput& f = wheel.forecast_input;
  e.km_per_day_se = f.km_per_day_se;
  e.day_km_sd = f.day_km_long_run_sd;
  e.km_per_day_dof = f.km_per_day_dof;
  e.clearance_now_se_mm = f.clearance_now_se_mm;
  e.clearance_rate_covariance = f.clearance_rate_covariance;
  e.critical_reached = wheel.critical.reached;
  e.critical_date = wheel.critical.date;
  e.warning_date = wheel.warning.reached ? "reached" : wheel.warning.date;
  if (plan.forecast) e.forecast = forecast_input_json(*plan.forecast);
  if (wheel.sensor_flag) {
    e.sensor_flag_first = wheel.sensor_flag->first_flagged;
    e.sensor_flag_confirmed = wheel.sensor_flag->confirmed;
  }
  return e;
}

}  // namespace

host::WearEstimateSet wear_estimate_set(const host::FleetWear& fleet, const host::StoreMarks& marks,
                                        const std::string& made_at) {
  host::WearEstimateSet set;
  set.made_at = made_at;
  set.marks = marks;
  set.warning_clearance_mm = fleet.warning_clearance_mm;
  set.critical_clearance_mm = fleet.critical_clearance_mm;
  set.max_step_mm = fleet.thresholds.max_step_mm;
  for (const host::WheelWear& wheel : fleet.wheels) set.wheels.push_back(estimate_record(wheel));
  return set;
}

std::string why_not_current(const std::optional<host::WearEstimateSet>& stored,
                            const host::StoreMarks& marks,
                            const host::ThresholdConfig& thresholds) {
  if (!stored) return "the store holds no estimates";
  if (stored->wheels.empty()) return "the stored estimates hold no wheel";
  const host::StoreMarks& then = stored->marks;
  if (marks.last_run_id != then.last_run_id) return "runs were stored after the estimates";
  if (marks.last_maintenance_id != then.last_maintenance_id) {
    return "maintenance was recorded after the estimates";
  }
  if (marks.last_calibration_id != then.last_calibration_id) {
    return "a calibration was stored after the estimates";
  }
  const double critical =
      thresholds.flange_nominal_mm + thresholds.sensor_gap_mm - thresholds.critical_flange_mm;
  if (stored->warning_clearance_mm != thresholds.warning_clearance_mm ||
      stored->critical_clearance_mm != critical || stored->max_step_mm != thresholds.max_step_mm) {
    return fmt::format(
        "the stored estimates were made with other limits (warning {} mm, critical {} mm, step "
        "{} mm)",
        stored->warning_clearance_mm, stored->critical_clearance_mm, stored->max_step_mm);
  }
  return "";
}

host::SensorFlags sensor_flags(const std::optional<host::WearEstimateSet>& stored,
                               const std::string& store_name) {
  host::SensorFlags flags;
  if (!stored) return flags;
  for (const host::WheelEstimateRecord& e : stored->wheels) {
    if (e.sensor_flag_first.empty() && e.sensor_flag_confirmed.empty()) continue;
    const auto refuse = [&](const std::string& why) {
      throw host::StoreError(fmt::format("store {}: wheel_estimates of {} axle {} {}: {}",
                                         store_name, e.wheel.locomotive, e.wheel.axle, e.wheel.side,
                                         why));
    };
    try {
      if (e.sensor_flag_first.empty()) refuse("sensor_flag_confirmed without sensor_flag_first");
      const double first = host::day_of_iso_time(e.sensor_flag_first);
      if (!e.sensor_flag_confirmed.empty() &&
          host::day_of_iso_time(e.sensor_flag_confirmed) < first) {
        refuse("sensor_flag_confirmed " + e.sensor_flag_confirmed +
               " is before sensor_flag_first " + e.sensor_flag_first);
      }
    } catch (const std::invalid_argument& error) {
      refuse(std::string("sensor flag: ") + error.what());
    }
    flags[{e.wheel.locomotive, e.wheel.axle, e.wheel.side}] = {e.sensor_flag_first,
                                                               e.sensor_flag_confirmed};
  }
  return flags;
}

std::vector<host::PlanInput> plan_inputs(const host::WearEstimateSet& stored) {
  std::vector<host::PlanInput> inputs;
  for (const host::WheelEstimateRecord& e : stored.wheels) {
    host::PlanInput input;
    input.wheel = {e.wheel.locomotive, e.wheel.axle, e.wheel.side, e.channel};
    input.status = e.status;
    input.has_forecast = e.has_fit && !e.last_run_at.empty() && e.km_per_day > 0.0;
    input.rate_mm_per_1000km = e.rate_mm_per_1000km;
    input.rate_low = e.rate_low;
    input.rate_high = e.rate_high;
    input.dof = e.rate_dof > 0 ? e.rate_dof : (e.has_fit ? e.fit_dof : 1);
    input.clearance_now_mm = e.clearance_now_mm;
    input.wear_now_mm = e.wear_now_mm;
    // The dates' forecast input when kept (schema version 7); an estimate stored before: the
    // rate's quantile alone, as the plan was then.
    if (!e.forecast.empty()) {
      try {
        input.forecast = forecast_input_of_json(e.forecast);
      } catch (const std::invalid_argument& error) {
        throw host::StoreError(fmt::format("wheel_estimates of {} axle {} {}: {}",
                                           e.wheel.locomotive, e.wheel.axle, e.wheel.side,
                                           error.what()));
      }
    }
    input.km_per_day = e.km_per_day;
    input.last_day = e.last_run_day;
    input.last_at = e.last_run_at;
    input.critical_reached = e.critical_reached;
    input.critical_date = e.critical_date;
    inputs.push_back(std::move(input));
  }
  return inputs;
}

}  // namespace flange::cli
