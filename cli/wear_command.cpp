// SPDX-License-Identifier: MIT
#include "wear_command.h"

#include <fmt/format.h>

#include <chrono>
#include <fstream>
#include <map>
#include <ostream>
#include <stdexcept>

#include "axle_clearance.h"
#include "calibration.h"
#include "cli.h"
#include "fleet_truth_check.h"
#include "fleet_truth_file.h"
#include "fleet_truth_match.h"
#include "fleet_wear.h"
#include "input_error.h"
#include "report_format.h"
#include "reprofiling_plan.h"
#include "sim_error.h"
#include "store.h"
#include "store_url.h"
#include "stored_wear_estimates.h"
#include "utc_time.h"
#include "version.h"
#include "wear_outputs.h"
#include "wear_report.h"

namespace flange::cli {
namespace {

using host::WheelHistory;

std::string key_text(const host::WheelKey& key) {
  return fmt::format("{}|{}|{}", key.locomotive, key.axle, key.side);
}

// Every wheel's runs with a clearance estimate, and its recorded maintenance, from the store
// (a few queries for the whole fleet: Store::wear_series).
std::vector<WheelHistory> read_histories(host::Store& store) {
  std::map<std::string, std::vector<host::MaintenanceMark>> maintenance;
  for (const host::StoredMaintenance& stored : store.maintenance_events("")) {
    const host::MaintenanceRecord& event = stored.event;
    maintenance[key_text(event.wheel)].push_back(
        {event.at, host::day_of_iso_time(event.at), event.odometer_km, event.kind});
  }
  std::vector<WheelHistory> histories;
  for (const host::WheelSeries& stored : store.wear_series()) {
    const host::WheelKey& key = stored.wheel.wheel;
    WheelHistory history;
    history.wheel = {key.locomotive, key.axle, key.side, stored.wheel.channel};
    for (const host::SeriesPoint& point : stored.points) {
      if (!point.clearance_mm) continue;  // a run without an estimate for this wheel
      history.runs.push_back({point.run_id, point.started_at,
                              host::day_of_iso_time(point.started_at), point.odometer_km,
                              *point.clearance_mm});
    }
    history.maintenance = maintenance[key_text(key)];
    if (!history.runs.empty()) histories.push_back(std::move(history));
  }
  return histories;
}

// The slope of the sensors' readings (mm/V) from the store's latest calibration, written beside
// the outputs as calibration.json; none when the store holds no calibration.
host::SensitivityAt store_sensitivity(host::Store& store, const std::filesystem::path& out_dir,
                                      std::ostream& out) {
  const auto calibrations = store.calibrations();
  if (calibrations.empty()) {
    out << "  the store holds no calibration: sensor drift is fitted in mm, not through the "
           "sensors' slope\n";
    return {};
  }
  const std::filesystem::path path = out_dir / "calibration.json";
  std::ofstream(path, std::ios::binary) << calibrations.back().second.model_json;
  return host::calibration_sensitivity(host::load_calibration(path.string()),
                                       host::kReferenceTempC);
}

// `flange wear` reads a store: a SQLite file that is not there is an error, not a new store.
std::unique_ptr<host::Store> open_existing_store(const std::string& url) {
  host::StoreUrl parsed;
  naming_option("--store", [&] { parsed = host::parse_store_url(url); });
  if (parsed.backend == host::StoreBackend::kSqlite && !std::filesystem::exists(parsed.target)) {
    throw host::StoreError("store " + parsed.shown + ": no such file");
  }
  return host::open_store(url);
}

// The --truth file; a file that is not one is named with the option ("--truth: FILE: ...").
sim::FleetTruth read_truth(const std::filesystem::path& path) {
  sim::FleetTruth truth;
  naming_option("--truth", [&] { truth = sim::read_fleet_truth(path); });
  return truth;
}

// Everything that can refuse the inputs, before anything is written: the truth file's fleet
// and the plan's risk and date against the store's runs.
void check_inputs(const WearOptions& options, const std::vector<WheelHistory>& histories) {
  if (options.truth) {
    check_truth_matches_runs(read_truth(*options.truth), histories, options.truth->string());
  }
  if (options.plan) {
    const auto [day, at] = host::last_run(histories);
    host::check_plan_request({options.before, options.risk}, day, at);
  }
}

// The plan's CSV, to its file (with its line on `out`) or, for `--plan-csv -`, to `out` alone.
void write_plan_csv_for(const WearOptions& options, const host::ReprofilingPlan& plan,
                        std::ostream& out) {
  const std::string csv_path = options.plan_csv.value_or((options.out / "plan.csv").string());
  if (csv_path == "-") {
    out << host::plan_csv(plan);
  } else {
    host::write_plan_csv(csv_path, plan);
    out << host::plan_summary_text(plan) << "  wrote " << csv_path << "\n";
  }
}

// --plan: the plan's CSV and its line on `out`; the page's section.
std::string write_plan(const WearOptions& options, const host::FleetWear& wear, std::ostream& out) {
  const host::ReprofilingPlan plan = host::plan_reprofiling(wear, {options.before, options.risk});
  write_plan_csv_for(options, plan, out);
  return host::plan_html_section(plan);
}

std::string utc_now() {
  const auto now = std::chrono::system_clock::now().time_since_epoch();
  return format_utc_time(std::chrono::duration<double>(now).count());
}

// --plan from the estimates the store keeps (current: nothing stored since they were made): the
// plan's CSV and a page of its own, without reading the runs or re-running the estimator.
int plan_from_stored(const WearOptions& options, host::Store& store,
                     const host::WearEstimateSet& stored, std::ostream& out, std::ostream& said) {
  const host::ReprofilingPlan plan = host::plan_reprofiling(
      plan_inputs(stored), stored.critical_clearance_mm, {options.before, options.risk});
  std::filesystem::create_directories(options.out);
  const std::string made = fmt::format(
      "the {} wheels' estimates that flange wear stored at {} (current: no run, maintenance or "
      "calibration stored since), not re-estimated",
      stored.wheels.size(), stored.made_at);
  said << fmt::format("wear: {} wheels from {}: the plan from {}\n", stored.wheels.size(),
                      store.name(), made);
  write_plan_csv_for(options, plan, out);
  std::ofstream page(options.out / "index.html", std::ios::binary);
  page << "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>Reprofiling plan</title>"
          "</head><body>\n<p>Made from "
       << coeffs::html_escape(made) << ".</p>\n"
       << host::plan_html_section(plan) << "</body></html>\n";
  page.close();
  if (!page) throw std::runtime_error("cannot write " + (options.out / "index.html").string());
  said << "  wrote " << (options.out / "index.html").string() << "\n";
  return kExitOk;
}

// The estimate kept in the store for the next plan; a store that refuses the write (a
// read-only role or replica) is said, not an error: the outputs are written already.
void keep_estimates(host::Store& store, const host::FleetWear& wear, const host::StoreMarks& marks,
                    std::ostream& said) {
  try {
    store.write_wear_estimates(wear_estimate_set(wear, marks, utc_now()));
    said << "  kept the " << wear.wheels.size()
         << " wheels' estimates in the store for the next --plan\n";
  } catch (const host::StoreError& error) {
    said << "  the estimates were not kept in the store: " << error.what() << "\n";
  }
}

// --truth: the comparison printed and written beside the outputs; false when it fails.
bool compare_with_truth(const WearOptions& options, const host::FleetWear& wear,
                        std::ostream& out) {
  const TruthCheck check = check_against_truth(wear, read_truth(*options.truth));
  const std::string text = truth_check_text(check);
  out << "\nagainst the truth in " << options.truth->string() << ":\n" << text;
  write_truth_check_json(options.out / "truth_check.json", check);
  std::ofstream(options.out / "truth_check.md", std::ios::binary) << text;
  return check.passed();
}

}  // namespace

CLI::App* add_wear_command(CLI::App& app, WearOptions& options) {
  CLI::App* cmd = app.add_subcommand(
      "wear",
      "Every wheel's flange wear from the runs in a store: rate per 1000 km, reprofilings, "
      "sensor faults and when each wheel reaches the warning and critical limits");
  cmd->add_option("--store", options.store, "the store: sqlite:PATH or postgresql://...")
      ->required();
  cmd->add_option("--out", options.out, "folder for wear.json, wear.csv and index.html")
      ->required();
  cmd->add_option("--truth", options.truth,
                  "a fleet scenario's truth file (fleet_truth.json) to compare the estimate with")
      ->check(CLI::ExistingFile);
  host::ThresholdConfig& t = options.thresholds;
  cmd->add_option("--warning-mm", t.warning_clearance_mm, "warning clearance (mm)")
      ->default_val(t.warning_clearance_mm);
  cmd->add_option("--critical-flange-mm", t.critical_flange_mm, "critical flange thickness (mm)")
      ->default_val(t.critical_flange_mm);
  cmd->add_option("--max-step-mm", t.max_step_mm,
                  "h of eq. 3.38: a larger fall of the clearance between runs is a reprofiling")
      ->default_val(t.max_step_mm);
  CLI::Option* plan =
      cmd->add_flag("--plan", options.plan,
                    "a reprofiling plan: the wheels to reprofile before --before at --risk, as "
                    "plan.csv and a section of index.html");
  cmd->add_option("--before", options.before,
                  "the plan's horizon: a date YYYY-MM-DD after the "
                  "last run")
      ->needs(plan);
  cmd->add_option("--risk", options.risk,
                  "the plan's chance of a wheel reaching the critical clearance before its date: "
                  "a probability strictly between 0 and 1")
      ->default_val(options.risk)
      ->needs(plan);
  cmd->add_option("--plan-csv", options.plan_csv,
                  "where the plan's CSV goes (default OUT/plan.csv; - for stdout, the summary "
                  "then on stderr)")
      ->needs(plan);
  return cmd;
}

int run_wear_command(const WearOptions& options, const std::vector<std::string>& command_line,
                     std::ostream& out, std::ostream& err) {
  host::validate(options.thresholds);
  if (options.plan && options.before.empty()) {
    throw host::InputError(
        "--before is required with --plan: a date YYYY-MM-DD after the "
        "last run");
  }
  const std::unique_ptr<host::Store> store = open_existing_store(options.store);
  // With the plan's CSV on stdout, the rest of what is said goes to stderr.
  std::ostream& said = options.plan && options.plan_csv == "-" ? err : out;
  // Read before the runs: a run stored while they are read leaves the estimate stale, not
  // wrongly current.
  const host::StoreMarks marks = store->marks();
  const std::optional<host::WearEstimateSet> stored = store->wear_estimates();
  const host::SensorFlags kept_flags = sensor_flags(stored, store->name());
  if (options.plan && !options.truth) {
    const std::string why = why_not_current(stored, marks, options.thresholds);
    if (why.empty()) return plan_from_stored(options, *store, *stored, out, said);
    said << "plan: re-estimating every wheel (" << why << ")\n";
  }
  const std::vector<WheelHistory> histories = read_histories(*store);
  if (histories.empty()) {
    throw std::runtime_error(store->name() + ": no run with a wheel's wear estimate");
  }
  check_inputs(options, histories);
  std::filesystem::create_directories(options.out);
  host::FleetWear wear = host::estimate_fleet_wear(histories, options.thresholds,
                                                   store_sensitivity(*store, options.out, said));
  host::latch_sensor_flags(wear, histories, kept_flags);
  const std::string generated_by = runtime::generated_by(command_line);
  host::write_wear_json(options.out / "wear.json", wear, generated_by);
  host::write_wear_csv(options.out / "wear.csv", wear);
  const std::string plan_section = options.plan ? write_plan(options, wear, out) : "";
  host::write_wear_report(options.out, wear, generated_by, plan_section);
  said << fmt::format("wear: {} wheels from {}, by days to the warning clearance ({} mm)\n",
                      wear.wheels.size(), store->name(), wear.warning_clearance_mm);
  said << host::fleet_wear_text(wear);
  const host::FleetAcceleration& bend = wear.acceleration;
  if (bend.dof > 0) {
    said << fmt::format(
        "  wear per km x exp(b wear) (1 + g day): b = {:.4f} per mm (se {:.4f}), g = {:.5f} per "
        "day "
        "(se {:.5f}), {} dof: {}\n",
        bend.estimate, bend.se, bend.trend, bend.trend_se, bend.dof,
        bend.significant ? "differs from 0 at 95 %"
                         : "within 0 at 95 %, weighed down in the dates");
  }
  const bool truth_ok = !options.truth || compare_with_truth(options, wear, said);
  said << "  wrote " << (options.out / "index.html").string() << ", wear.json and wear.csv\n";
  keep_estimates(*store, wear, marks, said);
  return truth_ok ? kExitOk : kExitFailure;
}

}  // namespace flange::cli
