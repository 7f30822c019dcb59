// SPDX-License-Identifier: MIT
// The measurement store at a national fleet's scale (docs/benchmarks.md, "Store"): a year of
// run summaries and alarm events ingested, then one wheel's wear history, the fleet table,
// `flange wear`'s nightly path (every wheel's runs read in bulk, the estimate, the estimates
// kept in the store) and the reprofiling plan as `flange wear --plan` makes it from the kept
// estimates (checked equal to the plan from the estimate itself: exit status 1 otherwise).
//
//   store_bench --store URL [--locomotives 1000] [--days 365] [--runs-per-transaction 100]
//               [--estimate-locomotives 100]
//
// A run is one locomotive's service day: its summary and 12 wheel rows (wear, clearance,
// temperature), and now and then an alarm event. 1,000 locomotives x 365 days = 365,000 runs of
// 4,380,000 wheel rows. The numbers are made up here (wear linear in distance plus noise, a
// reprofiling, a maintenance event of its own transaction, when a wheel reaches 4 mm: about once
// a year per wheel): the store's work does not depend on them. Prints one line of figures; the
// URL must name an empty store. The nightly read is of the whole fleet; the estimate (which does
// not touch the store) and so the estimates kept and the plan are of the first
// --estimate-locomotives locomotives' wheels (0: none).
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <iostream>
#include <map>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "fleet_wear.h"
#include "reprofiling_plan.h"
#include "store.h"
#include "stored_wear_estimates.h"

namespace {

using flange::host::RunRecord;
using flange::host::Store;
using Clock = std::chrono::steady_clock;

struct Settings {
  std::string url;
  int locomotives = 1000;
  int days = 365;
  int runs_per_transaction = 100;
  int estimate_locomotives = 100;
};

struct Counts {
  std::uint64_t runs = 0, wheel_rows = 0, alarm_rows = 0, maintenance = 0;
};

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

std::string day_time(int day, int locomotive) {
  const int month_days[] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  int month = 0;
  while (day >= month_days[month]) day -= month_days[month++];
  return fmt::format("2025-{:02d}-{:02d}T{:02d}:{:02d}:00Z", month + 1, day + 1,
                     5 + locomotive % 12, locomotive % 60);
}

// One locomotive's day; `wear` (12 wheels) and `odometer` advance.
RunRecord service_day(int locomotive, int day, std::vector<double>& wear, double& odometer,
                      std::mt19937_64& random, Store& store, Counts& counts) {
  std::normal_distribution<double> noise(0.0, 0.02);
  std::uniform_real_distribution<double> distance(250.0, 450.0);
  RunRecord run;
  run.locomotive = fmt::format("loco-{:03d}", locomotive);
  run.started_at = day_time(day, locomotive);
  run.distance_km = distance(random);
  odometer += run.distance_km;
  run.odometer_km = odometer;
  run.coefficient_set = "coeffs/measurement_sos/filter.json";
  run.coefficient_sha256 = std::string(64, 'c');
  run.engine = "model";
  run.sample_rate_hz = 100.0;
  run.rows = 12 * 30000;
  run.summary_json = R"({"bench": true})";
  for (int channel = 0; channel < 12; ++channel) {
    double& w = wear[static_cast<std::size_t>(channel)];
    w += run.distance_km * (0.02 + 0.002 * channel) / 1000.0;
    const int axle = channel / 2 + 1;
    const std::string side = channel % 2 ? "right" : "left";
    if (w > 4.0) {  // the depot reprofiles it
      store.record_maintenance({{run.locomotive, axle, side},
                                run.started_at,
                                odometer,
                                "reprofile",
                                "store_bench",
                                std::nullopt});
      ++counts.maintenance;
      w = 0.0;
    }
    flange::host::WheelRunResult wheel;
    wheel.axle = axle;
    wheel.side = side;
    wheel.channel = channel;
    wheel.wear_mm = w + noise(random);
    wheel.clearance_mm = 3.0 + *wheel.wear_mm;
    wheel.temp_c = 15.0 + 10.0 * noise(random);
    wheel.samples = 30000;
    run.wheels.push_back(wheel);
    if (w > 3.0 && random() % 8 == 0) run.alarms.push_back({axle, side, 120.0, "warning"});
  }
  counts.wheel_rows += run.wheels.size();
  counts.alarm_rows += run.alarms.size();
  ++counts.runs;
  return run;
}

double ingest(Store& store, const Settings& settings, Counts& counts) {
  std::mt19937_64 random(20251);
  std::vector<std::vector<double>> wear(static_cast<std::size_t>(settings.locomotives),
                                        std::vector<double>(12, 0.0));
  for (auto& wheels : wear) {
    for (double& w : wheels) w = std::uniform_real_distribution<double>(0.0, 3.5)(random);
  }
  std::vector<double> odometer(static_cast<std::size_t>(settings.locomotives), 100000.0);
  std::vector<RunRecord> batch;
  const auto start = Clock::now();
  for (int day = 0; day < settings.days; ++day) {
    for (int loco = 0; loco < settings.locomotives; ++loco) {
      const auto l = static_cast<std::size_t>(loco);
      batch.push_back(service_day(loco, day, wear[l], odometer[l], random, store, counts));
      if (static_cast<int>(batch.size()) == settings.runs_per_transaction) {
        store.record_runs(batch);
        batch.clear();
      }
    }
  }
  if (!batch.empty()) store.record_runs(batch);
  return seconds_since(start);
}

// Median and largest time (ms) of one wheel's history, over wheels spread across the fleet.
std::pair<double, double> history_ms(Store& store, const Settings& settings, std::size_t& rows) {
  std::vector<double> times;
  for (int i = 0; i < 24; ++i) {
    const flange::host::WheelKey wheel{fmt::format("loco-{:03d}", (i * 37) % settings.locomotives),
                                       i % 6 + 1, i % 2 ? "right" : "left"};
    const auto start = Clock::now();
    rows = store.wear_history(wheel).size();
    times.push_back(1000.0 * seconds_since(start));
  }
  std::sort(times.begin(), times.end());
  return {times[times.size() / 2], times.back()};
}

struct PlanTimes {
  double read_s = 0.0, estimate_s = 0.0, keep_s = 0.0, plan_s = 0.0;
  std::size_t wheels = 0, estimated_wheels = 0, due = 0;
  bool same = false;  // the plan from the stored estimates is the one from the estimate
};

// Every wheel's runs and the maintenance records as `flange wear` reads them.
std::vector<flange::host::WheelHistory> read_histories(Store& store) {
  const std::vector<flange::host::WheelSeries> series = store.wear_series();
  const std::vector<flange::host::StoredMaintenance> maintenance = store.maintenance_events("");
  std::vector<flange::host::WheelHistory> histories;
  for (const flange::host::WheelSeries& wheel : series) {
    flange::host::WheelHistory history;
    const flange::host::WheelKey& key = wheel.wheel.wheel;
    history.wheel = {key.locomotive, key.axle, key.side, wheel.wheel.channel};
    for (const flange::host::SeriesPoint& point : wheel.points) {
      history.runs.push_back({point.run_id, point.started_at,
                              flange::host::day_of_iso_time(point.started_at), point.odometer_km,
                              point.clearance_mm.value_or(0.0)});
    }
    histories.push_back(std::move(history));
  }
  std::map<std::tuple<std::string, int, std::string>, flange::host::WheelHistory*> by_key;
  for (flange::host::WheelHistory& history : histories) {
    by_key[{history.wheel.locomotive, history.wheel.axle, history.wheel.side}] = &history;
  }
  for (const flange::host::StoredMaintenance& stored : maintenance) {
    const flange::host::MaintenanceRecord& event = stored.event;
    const auto at = by_key.find({event.wheel.locomotive, event.wheel.axle, event.wheel.side});
    if (at == by_key.end()) continue;
    at->second->maintenance.push_back(
        {event.at, flange::host::day_of_iso_time(event.at), event.odometer_km, event.kind});
  }
  return histories;
}

// The plan as `flange wear --plan` makes it from current stored estimates: the store's marks and
// estimates read, checked current, the plan made.
flange::host::ReprofilingPlan plan_from_store(Store& store,
                                              const flange::host::PlanRequest& request) {
  const flange::host::StoreMarks marks = store.marks();
  const std::optional<flange::host::WearEstimateSet> stored = store.wear_estimates();
  const std::string why = flange::cli::why_not_current(stored, marks, {});
  if (!why.empty()) throw std::runtime_error("the stored estimates are not current: " + why);
  return flange::host::plan_reprofiling(flange::cli::plan_inputs(*stored),
                                        stored->critical_clearance_mm, request);
}

// `flange wear`'s nightly path (every wheel's runs read, the estimate, the estimates kept in the
// store), then `flange wear --plan`'s from the stored estimates (median of 3), checked against
// the plan made from the estimate itself.
PlanTimes plan_times(Store& store, int estimate_locomotives) {
  PlanTimes times;
  const flange::host::StoreMarks marks = store.marks();
  auto start = Clock::now();
  std::vector<flange::host::WheelHistory> histories = read_histories(store);
  times.read_s = seconds_since(start);
  times.wheels = histories.size();
  if (estimate_locomotives == 0) return times;
  // The first locomotives by number ("loco-NNN"; "loco-1000" would sort before "loco-101").
  std::erase_if(histories, [&](const flange::host::WheelHistory& history) {
    return std::stoi(history.wheel.locomotive.substr(5)) >= estimate_locomotives;
  });
  start = Clock::now();
  const flange::host::FleetWear wear = flange::host::estimate_fleet_wear(histories, {});
  times.estimate_s = seconds_since(start);
  times.estimated_wheels = histories.size();
  start = Clock::now();
  store.write_wear_estimates(flange::cli::wear_estimate_set(wear, marks, "2026-01-01T00:00:00Z"));
  times.keep_s = seconds_since(start);
  const flange::host::PlanRequest request{"2027-01-01", 0.05};
  std::vector<double> plan_s;
  flange::host::ReprofilingPlan stored_plan;
  for (int i = 0; i < 3; ++i) {
    start = Clock::now();
    stored_plan = plan_from_store(store, request);
    plan_s.push_back(seconds_since(start));
  }
  std::sort(plan_s.begin(), plan_s.end());
  times.plan_s = plan_s[1];
  times.due = stored_plan.wheels.size();
  times.same = flange::host::plan_csv(stored_plan) ==
               flange::host::plan_csv(flange::host::plan_reprofiling(wear, request));
  return times;
}

Settings parse(int argc, char** argv) {
  Settings settings;
  for (int i = 1; i < argc; i += 2) {
    const std::string key = argv[i];
    if (i + 1 >= argc) throw std::invalid_argument(key + " needs a value");
    const std::string value = argv[i + 1];
    if (key == "--store")
      settings.url = value;
    else if (key == "--locomotives")
      settings.locomotives = std::stoi(value);
    else if (key == "--days")
      settings.days = std::stoi(value);
    else if (key == "--estimate-locomotives")
      settings.estimate_locomotives = std::stoi(value);
    else if (key == "--runs-per-transaction")
      settings.runs_per_transaction = std::stoi(value);
    else
      throw std::invalid_argument("unknown option " + key);
  }
  if (settings.url.empty() || settings.locomotives < 1 || settings.days < 1 ||
      settings.days > 365 || settings.runs_per_transaction < 1 ||
      settings.estimate_locomotives < 0 || settings.estimate_locomotives > settings.locomotives) {
    throw std::invalid_argument(
        "usage: store_bench --store URL [--locomotives N] [--days 1..365] "
        "[--runs-per-transaction N] [--estimate-locomotives 0..N]");
  }
  return settings;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const Settings settings = parse(argc, argv);
    const auto store = flange::host::open_store(settings.url);
    if (store->run_count() != 0) throw std::invalid_argument(settings.url + " is not empty");
    Counts counts;
    const double ingest_s = ingest(*store, settings, counts);
    std::size_t history_rows = 0;
    const auto [history_median, history_max] = history_ms(*store, settings, history_rows);
    std::vector<double> fleet_times;
    std::size_t fleet_rows = 0;
    for (int i = 0; i < 3; ++i) {
      const auto start = Clock::now();
      fleet_rows = store->fleet_table().size();
      fleet_times.push_back(seconds_since(start));
    }
    std::sort(fleet_times.begin(), fleet_times.end());
    const PlanTimes plan = plan_times(*store, settings.estimate_locomotives);
    const std::uint64_t rows = counts.runs + counts.wheel_rows + counts.alarm_rows;
    const bool estimated = plan.estimated_wheels > 0;
    fmt::print(
        "| {} | {} x {} d | {} | {} | {} | {:.0f} | {:.0f} | {:.1f} ({:.1f}) | {} | "
        "{:.1f} ({}) | {:.1f} ({}) | {} | {} | {} | {} | {:.0f} |\n",
        store->backend(), settings.locomotives, settings.days, counts.runs, counts.wheel_rows,
        counts.alarm_rows, ingest_s, static_cast<double>(rows) / ingest_s, history_median,
        history_max, history_rows, 1000.0 * fleet_times[1], fleet_rows, plan.read_s, plan.wheels,
        estimated ? fmt::format("{:.1f} ({})", plan.estimate_s, plan.estimated_wheels) : "-",
        estimated ? fmt::format("{:.2f}", plan.keep_s) : "-",
        estimated ? fmt::format("{:.0f} ({})", 1000.0 * plan.plan_s, plan.estimated_wheels) : "-",
        estimated ? fmt::format("{}{}", plan.due, plan.same ? "" : " (DIFFERS)") : "-",
        static_cast<double>(store->size_bytes()) / 1e6);
    return plan.estimated_wheels == 0 || plan.same ? 0 : 1;
  } catch (const std::invalid_argument& error) {
    std::cerr << "store_bench: " << error.what() << "\n";
    return 2;
  } catch (const std::exception& error) {
    std::cerr << "store_bench: " << error.what() << "\n";
    return 1;
  }
}
