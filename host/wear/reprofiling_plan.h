// SPDX-License-Identifier: MIT
// The reprofiling plan: which wheels must go to the lathe before a date, and by when each, so
// that the chance of a wheel reaching the critical clearance before its reprofiling is at most
// a chosen risk P. Built on the estimator's forecast (fleet_wear.h, limit_forecast.h): a wheel
// reaches the critical clearance by a distance d when its rate is at least gap / d (or, with the
// fleet's acceleration b, (1 - exp(-b gap)) / b), so the date at which that chance is P is the
// one its current flange reaches the limit at the rate's (1 - P) quantile. That quantile is the
// forecast's rate (moved by b, as the dates' is) plus the rate's stated 95 % half-width scaled
// by the Student t quantiles of the fit's degrees of freedom (the upper half of the interval for
// P under 1/2, the lower half above), and the date is forecast_limit's at that rate from the
// forecast's clearance now with the same b, so at P = 1/2 it is the critical date; the
// intercept's uncertainty is not added (as in the forecast). docs/fleet.md, "Reprofiling plan".
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "fleet_wear.h"

namespace flange::host {

struct PlanRequest {
  std::string before;  // "YYYY-MM-DD": the plan's horizon, after the last run
  double risk = 0.05;  // the chance of reaching the critical clearance first, in (0, 1)
};

// What the plan needs of one wheel's estimate: made from the estimator's WheelWear
// (plan_input) or read back from the estimates a store keeps (the same numbers, so the same
// plan).
struct PlanInput {
  WheelId wheel;
  std::string status;
  bool has_forecast = false;  // a wear line, runs and a positive km per day
  double rate_mm_per_1000km = 0.0, rate_low = 0.0, rate_high = 0.0;  // 95 % interval
  int dof = 1;  // Student t's for the stated interval
  double clearance_now_mm = 0.0, wear_now_mm = 0.0;
  // The clearance now and the rate as the dates' forecast has them (fleet_wear.cpp's
  // forecast_input: moved by the fleet's acceleration, the interval with the rate), and that
  // acceleration b per mm: 0 when the dates are the straight line's (the fleet's b within 0 at
  // 95 %, or the wheel's drift fitted out), and then the two are the fitted ones above, so the
  // plan is the straight line's to the bit.
  double forecast_clearance_now_mm = 0.0, forecast_rate_mm_per_1000km = 0.0;
  double acceleration_per_mm = 0.0;
  double km_per_day = 0.0;
  double last_day = 0.0;  // the wheel's last run, days since 1970-01-01
  std::string last_at;    // the same, ISO 8601
  bool critical_reached = false;
  std::string critical_date;  // at the fitted rate
};

PlanInput plan_input(const WheelWear& wheel);

struct PlannedWheel {
  WheelId wheel;
  std::string status;        // the estimator's ("ok", "sensor fault", ...)
  std::string due_date;      // reprofile on or before this date (YYYY-MM-DD)
  double due_day = 0.0;      // the same in days since 1970-01-01 (with its fraction)
  bool reached = false;      // the fitted clearance is at the critical limit already
  double wear_now_mm = 0.0;  // the estimator's, at the last run
  double rate_mm_per_1000km = 0.0;
  double rate_at_risk_mm_per_1000km = 0.0;  // the forecast's rate's (1 - risk) quantile
  std::string critical_date;                // at the fitted rate; "" when it does not wear
};

struct ReprofilingPlan {
  PlanRequest request;
  double before_day = 0.0;           // midnight starting `before`
  std::string last_run_at;           // the latest run of any wheel
  std::vector<PlannedWheel> wheels;  // due before `before`, soonest first
  // Wheels without a forecast (too few runs, or a locomotive that never moved): not planned.
  std::vector<PlanInput> unplanned;
};

// Throws InputError (exit status 2) naming the option and its valid range when the risk is not
// strictly between 0 and 1, `before` is not a date, or it is not after `last_run_day` (days
// since 1970-01-01 of the latest run; `last_run_at` names it in the message).
void check_plan_request(const PlanRequest& request, double last_run_day,
                        const std::string& last_run_at);

// The latest run over the histories: (day, ISO time). Histories must not be empty.
std::pair<double, std::string> last_run(const std::vector<WheelHistory>& histories);

// The rate (mm per 1000 km) that a wheel's true rate exceeds with probability `risk`: the
// forecast's rate (with b, the rate at the last run as the bend has it) and the stated interval's
// half-widths (b moves the rate and both ends alike).
double rate_at_risk(const PlanInput& wheel, double risk);
double rate_at_risk(const WheelWear& wheel, double risk);

// The plan over the estimator's fleet (check_plan_request first: throws as it does).
ReprofilingPlan plan_reprofiling(const FleetWear& fleet, const PlanRequest& request);
// The same over the wheels' plan inputs, with the critical clearance they were forecast to.
// Wheels due on the same day are listed by locomotive, axle, side.
ReprofilingPlan plan_reprofiling(const std::vector<PlanInput>& wheels, double critical_clearance_mm,
                                 const PlanRequest& request);

// plan.csv: one row per planned wheel, soonest first.
std::string plan_csv(const ReprofilingPlan& plan);
void write_plan_csv(const std::filesystem::path& path, const ReprofilingPlan& plan);

// The plan as a section of the wear page (HTML, escaped).
std::string plan_html_section(const ReprofilingPlan& plan);

// One line for stdout: how many wheels are due and the first of them.
std::string plan_summary_text(const ReprofilingPlan& plan);

}  // namespace flange::host
