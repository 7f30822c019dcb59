// SPDX-License-Identifier: MIT
// The reprofiling plan: which wheels must go to the lathe before a date, and by when each, so
// that the chance of a wheel reaching the critical clearance before its reprofiling is at most
// a chosen risk P. Built on the estimator's forecast (fleet_wear.h, limit_forecast.h): a wheel's
// due date at risk P is the P quantile of its critical date under the same distribution the
// dates' interval states (the clearance now, the rate, the mean km per day and the km to come,
// the fleet's acceleration with its uncertainty; Student t at their Welch-Satterthwaite degrees
// of freedom): forecast_limit's lower bound at the two-sided level 1 - 2P for P under 1/2 (its
// one-sided 1 - P), its point date at 1/2, its upper bound at 2P - 1 above (none when that bound
// is open). So the plan holds as well as the dates' interval does. A wheel whose forecast input
// is not known (an estimate stored before schema version 7) or states no spread (dof 0) is
// planned as before: its current flange at the critical clearance at the rate's (1 - P)
// quantile. docs/fleet.md, "Reprofiling plan".
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "fleet_wear.h"
#include "limit_forecast.h"

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
  // The dates' whole forecast input (fleet_wear.cpp's forecast_input: the clearance now and the
  // rate moved by the fleet's acceleration, their uncertainties, the km per day's and b's), from
  // which the due date is the critical date's quantile; nothing for an estimate stored before
  // schema version 7, planned on the rate's quantile alone.
  std::optional<ForecastInput> forecast;
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
  // The forecast's rate's (1 - risk) quantile alone: the date from it when the wheel is planned
  // on the rate (no forecast input kept); otherwise reported beside the date's quantile, which
  // also holds the km per day's uncertainty and is sooner at a risk under 1/2.
  double rate_at_risk_mm_per_1000km = 0.0;
  bool on_rate_alone = false;  // planned on the rate's quantile alone (no forecast input kept)
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

// The rate (mm per 1000 km) that a wheel's true rate exceeds with probability `risk`, its
// uncertainty alone: the forecast's rate (with b, the rate at the last run as the bend has it)
// and the stated interval's half-widths (b moves the rate and both ends alike). The plan's date
// for a wheel without a forecast input; reported beside the date's quantile otherwise.
double rate_at_risk(const PlanInput& wheel, double risk);
double rate_at_risk(const WheelWear& wheel, double risk);

// The days from the forecast's last run to the wheel's critical date's `risk` quantile: the
// dates' interval's lower bound at the two-sided level 1 - 2 risk under 1/2, its point at 1/2,
// its upper bound at 2 risk - 1 above; nothing when that date is not known or the bound is open
// (0 when the limit is reached).
std::optional<double> critical_days_at_risk(const ForecastInput& input,
                                            double critical_clearance_mm, double risk);

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
