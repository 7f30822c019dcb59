// SPDX-License-Identifier: MIT
#include "reprofiling_plan.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <stdexcept>
#include <tuple>

#include "input_error.h"
#include "limit_forecast.h"
#include "report_format.h"
#include "wear_line_fit.h"

namespace flange::host {
namespace {

// "YYYY-MM-DD" and nothing else, as days since 1970-01-01; InputError otherwise.
double day_of_plan_date(const std::string& text) {
  const bool shaped = text.size() == 10 && text[4] == '-' && text[7] == '-' &&
                      std::all_of(text.begin(), text.end(),
                                  [](char c) { return c == '-' || (c >= '0' && c <= '9'); });
  try {
    if (shaped) return day_of_iso_time(text);
  } catch (const std::invalid_argument&) {
  }
  throw InputError(fmt::format("--before: '{}' is not a date: YYYY-MM-DD, after the last run",
                               printable_excerpt(text)));
}

// Whether the wheel's forecast moved its clearance and rate by the fleet's acceleration.
bool bent_by_acceleration(const PlanInput& wheel) {
  return wheel.forecast && wheel.forecast->acceleration_per_mm != 0.0;
}

// How many of the plan's wheels are dated on their rate's quantile alone (no forecast input).
long wheels_on_rate_alone(const ReprofilingPlan& plan) {
  return static_cast<long>(std::count_if(plan.wheels.begin(), plan.wheels.end(),
                                         [](const PlannedWheel& w) { return w.on_rate_alone; }));
}

// The forecast at the rate at risk alone (a wheel without a usable forecast input): the straight
// line from the fitted clearance, or the bent forecast's clearance and b when it has them.
LimitForecast forecast_at_rate(const PlanInput& wheel, double critical_clearance_mm, double rate) {
  ForecastInput input;
  const bool bent = bent_by_acceleration(wheel);
  input.clearance_now_mm = bent ? wheel.forecast->clearance_now_mm : wheel.clearance_now_mm;
  input.acceleration_per_mm = bent ? wheel.forecast->acceleration_per_mm : 0.0;
  input.rate_mm_per_km = input.rate_low_mm_per_km = input.rate_high_mm_per_km = rate / 1000.0;
  input.km_per_day = wheel.km_per_day;
  input.last_day = wheel.last_day;
  return forecast_limit(input, critical_clearance_mm);
}

// The wheel's plan entry: its critical date's quantile at the risk, from its forecast input (or
// its rate's quantile alone without one); nothing without a forecast.
std::optional<PlannedWheel> planned_wheel(const PlanInput& wheel, double critical_clearance_mm,
                                          double risk) {
  if (!wheel.has_forecast) return std::nullopt;
  PlannedWheel planned;
  planned.wheel = wheel.wheel;
  planned.status = wheel.status;
  planned.wear_now_mm = wheel.wear_now_mm;
  planned.rate_mm_per_1000km = wheel.rate_mm_per_1000km;
  planned.rate_at_risk_mm_per_1000km = rate_at_risk(wheel, risk);
  planned.critical_date = wheel.critical_reached ? "reached" : wheel.critical_date;
  planned.on_rate_alone = !wheel.forecast || wheel.forecast->dof <= 0;
  std::optional<double> days;
  if (planned.on_rate_alone) {
    const LimitForecast at_rate =
        forecast_at_rate(wheel, critical_clearance_mm, planned.rate_at_risk_mm_per_1000km);
    planned.reached = at_rate.reached;
    days = at_rate.days;
  } else {
    planned.reached = forecast_limit(*wheel.forecast, critical_clearance_mm).reached;
    days = critical_days_at_risk(*wheel.forecast, critical_clearance_mm, risk);
  }
  if (!days) return planned;  // never at this risk: due_date stays ""
  planned.due_day = (planned.on_rate_alone ? wheel.last_day : wheel.forecast->last_day) + *days;
  planned.due_date = date_of_day(planned.due_day);
  return planned;
}

std::string wheel_text(const WheelId& wheel) {
  return fmt::format("{} axle {} {}", wheel.locomotive, wheel.axle, wheel.side);
}

// A CSV field: quoted when it holds a comma, a quote or a line break.
std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

}  // namespace

void check_plan_request(const PlanRequest& request, double last_run_day,
                        const std::string& last_run_at) {
  if (!(request.risk > 0.0 && request.risk < 1.0)) {
    throw InputError(
        fmt::format("--risk: {} is outside its valid range: a probability strictly between 0 and 1",
                    request.risk));
  }
  const double before_day = day_of_plan_date(request.before);
  if (!(before_day > std::floor(last_run_day))) {
    throw InputError(fmt::format(
        "--before: {} is not after the store's last run ({}): a date YYYY-MM-DD after {}",
        request.before, printable_excerpt(last_run_at), date_of_day(last_run_day)));
  }
}

std::pair<double, std::string> last_run(const std::vector<WheelHistory>& histories) {
  std::pair<double, std::string> latest{-INFINITY, ""};
  for (const WheelHistory& history : histories) {
    for (const WearObservation& run : history.runs) {
      if (run.day > latest.first) latest = {run.day, run.at};
    }
  }
  if (histories.empty() || latest.second.empty()) {
    throw std::invalid_argument("last_run: no runs");
  }
  return latest;
}

PlanInput plan_input(const WheelWear& wheel) {
  PlanInput input;
  input.wheel = wheel.wheel;
  input.status = wheel.status;
  input.has_forecast = wheel.fit && !wheel.runs.empty() && wheel.km_per_day > 0.0;
  input.rate_mm_per_1000km = wheel.rate_mm_per_1000km;
  input.rate_low = wheel.rate_low;
  input.rate_high = wheel.rate_high;
  // The stated interval's own degrees of freedom (the block jackknife's, fleet_wear.h).
  input.dof = wheel.rate_dof > 0 ? wheel.rate_dof : (wheel.fit ? wheel.fit->dof : 1);
  input.clearance_now_mm = wheel.clearance_now_mm;
  input.wear_now_mm = wheel.wear_now_mm;
  if (wheel.fit) input.forecast = wheel.forecast_input;
  input.km_per_day = wheel.km_per_day;
  if (!wheel.runs.empty()) {
    input.last_day = wheel.runs.back().day;
    input.last_at = wheel.runs.back().at;
  }
  input.critical_reached = wheel.critical.reached;
  input.critical_date = wheel.critical.date;
  return input;
}

double rate_at_risk(const PlanInput& wheel, double risk) {
  const double t = t_one_sided(1.0 - risk, wheel.dof);
  const double t_stated = t95(wheel.dof);
  // The half of the stated interval on the side the quantile lies (they differ when the
  // interval is not symmetric about the rate).
  const double half = t >= 0.0 ? wheel.rate_high - wheel.rate_mm_per_1000km
                               : wheel.rate_mm_per_1000km - wheel.rate_low;
  // The bent forecast's rate when the fleet's acceleration moved it, else the fitted one.
  const bool bent = bent_by_acceleration(wheel);
  const double rate = bent ? wheel.forecast->rate_mm_per_km * 1000.0 : wheel.rate_mm_per_1000km;
  return rate + t * half / t_stated;
}

std::optional<double> critical_days_at_risk(const ForecastInput& input,
                                            double critical_clearance_mm, double risk) {
  if (risk == 0.5) return forecast_limit(input, critical_clearance_mm).days;
  const LimitForecast bounds =
      forecast_limit(input, critical_clearance_mm, std::abs(1.0 - 2.0 * risk));
  return risk < 0.5 ? bounds.days_low : bounds.days_high;
}

double rate_at_risk(const WheelWear& wheel, double risk) {
  return rate_at_risk(plan_input(wheel), risk);
}

ReprofilingPlan plan_reprofiling(const FleetWear& fleet, const PlanRequest& request) {
  std::vector<PlanInput> wheels;
  for (const WheelWear& wheel : fleet.wheels) wheels.push_back(plan_input(wheel));
  return plan_reprofiling(wheels, fleet.critical_clearance_mm, request);
}

ReprofilingPlan plan_reprofiling(const std::vector<PlanInput>& wheels, double critical_clearance_mm,
                                 const PlanRequest& request) {
  ReprofilingPlan plan;
  plan.request = request;
  double last_day = -INFINITY;
  for (const PlanInput& wheel : wheels) {
    if (!wheel.last_at.empty() && wheel.last_day > last_day) {
      last_day = wheel.last_day;
      plan.last_run_at = wheel.last_at;
    }
  }
  check_plan_request(request, last_day, plan.last_run_at);
  plan.before_day = day_of_plan_date(request.before);
  for (const PlanInput& wheel : wheels) {
    const std::optional<PlannedWheel> planned =
        planned_wheel(wheel, critical_clearance_mm, request.risk);
    if (!planned) {
      plan.unplanned.push_back(wheel);
    } else if (!planned->due_date.empty() && planned->due_day < plan.before_day) {
      plan.wheels.push_back(*planned);
    }
  }
  const auto key = [](const PlannedWheel& w) {
    return std::tie(w.due_day, w.wheel.locomotive, w.wheel.axle, w.wheel.side);
  };
  std::sort(plan.wheels.begin(), plan.wheels.end(),
            [&](const PlannedWheel& a, const PlannedWheel& b) { return key(a) < key(b); });
  std::sort(plan.unplanned.begin(), plan.unplanned.end(),
            [](const PlanInput& a, const PlanInput& b) {
              return std::tie(a.wheel.locomotive, a.wheel.axle, a.wheel.side) <
                     std::tie(b.wheel.locomotive, b.wheel.axle, b.wheel.side);
            });
  return plan;
}

std::string plan_csv(const ReprofilingPlan& plan) {
  std::string csv =
      "locomotive,axle,side,due_date,status,wear_now_mm,rate_mm_per_1000km,"
      "rate_at_risk_mm_per_1000km,critical_date_at_rate\n";
  for (const PlannedWheel& w : plan.wheels) {
    csv += fmt::format("{},{},{},{},{},{:.3f},{:.4f},{:.4f},{}\n", csv_field(w.wheel.locomotive),
                       w.wheel.axle, w.wheel.side, w.due_date, csv_field(w.status), w.wear_now_mm,
                       w.rate_mm_per_1000km, w.rate_at_risk_mm_per_1000km, w.critical_date);
  }
  return csv;
}

void write_plan_csv(const std::filesystem::path& path, const ReprofilingPlan& plan) {
  std::ofstream file(path, std::ios::binary);
  file << plan_csv(plan);
  file.close();
  if (!file) throw std::runtime_error("cannot write " + path.string());
}

std::string plan_html_section(const ReprofilingPlan& plan) {
  std::string html = fmt::format(
      "<h2>Reprofiling plan before {}</h2>\n<p>{} wheels must be reprofiled before {} for a risk "
      "of {:g} % of reaching the critical clearance first (each wheel's date: the one its "
      "critical date falls before with that probability, the dates' forecast's quantile, from "
      "the last run, {}; the rate at risk is the rate's quantile alone). Soonest first.</p>\n",
      coeffs::html_escape(plan.request.before), plan.wheels.size(),
      coeffs::html_escape(plan.request.before), 100.0 * plan.request.risk,
      coeffs::html_escape(plan.last_run_at));
  html +=
      "<table><tr><th>reprofile by</th><th>locomotive</th><th>wheel</th><th>status</th>"
      "<th>wear now (mm)</th><th>rate (mm/1000 km)</th><th>rate at risk</th>"
      "<th>critical at the rate</th></tr>\n";
  for (const PlannedWheel& w : plan.wheels) {
    html += fmt::format(
        "<tr><td>{}</td><td>{}</td><td>axle {} {}</td><td>{}</td><td>{:.3f}</td><td>{:.4f}</td>"
        "<td>{:.4f}</td><td>{}</td></tr>\n",
        w.reached ? w.due_date + " (reached)" : w.due_date, coeffs::html_escape(w.wheel.locomotive),
        w.wheel.axle, w.wheel.side, coeffs::html_escape(w.status), w.wear_now_mm,
        w.rate_mm_per_1000km, w.rate_at_risk_mm_per_1000km,
        w.critical_date.empty() ? "-" : w.critical_date);
  }
  html += "</table>\n";
  const long on_rate = wheels_on_rate_alone(plan);
  if (on_rate > 0) {
    html += fmt::format(
        "<p>{} of these wheels' estimates keep no forecast input (stored before schema version "
        "7): their dates are the critical clearance at the rate at risk alone, without the km "
        "per day's uncertainty.</p>\n",
        on_rate);
  }
  if (!plan.unplanned.empty()) {
    html += "<p>Not planned (no forecast: too few runs, or no distance run):";
    for (const PlanInput& w : plan.unplanned) {
      html += " " + coeffs::html_escape(wheel_text(w.wheel)) + ";";
    }
    html += "</p>\n";
  }
  return html;
}

std::string plan_summary_text(const ReprofilingPlan& plan) {
  std::string text = fmt::format("plan: {} wheels to reprofile before {} at a risk of {:g}\n",
                                 plan.wheels.size(), plan.request.before, plan.request.risk);
  if (!plan.wheels.empty()) {
    text += fmt::format("  first: {} by {}\n", wheel_text(plan.wheels.front().wheel),
                        plan.wheels.front().due_date);
  }
  const long on_rate = wheels_on_rate_alone(plan);
  if (on_rate > 0) {
    text += fmt::format("  {} wheels planned on the rate at risk alone (no forecast input kept)\n",
                        on_rate);
  }
  if (!plan.unplanned.empty()) {
    text += fmt::format("  {} wheels without a forecast are not planned\n", plan.unplanned.size());
  }
  return text;
}

}  // namespace flange::host
