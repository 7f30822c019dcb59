// SPDX-License-Identifier: MIT
#include "fleet_truth_match.h"

#include <fmt/format.h>

#include <cmath>
#include <map>
#include <set>

#include "input_error.h"
#include "limit_forecast.h"

namespace flange::cli {
namespace {

[[noreturn]] void another_fleet(const std::string& file, const std::string& what) {
  throw host::InputError(fmt::format("--truth {}: the truth of another fleet: {}",
                                     host::printable_excerpt(file, 80), what));
}

// Each locomotive's runs (one wheel's history stands for its runs) by day, from the store.
std::map<std::string, const host::WheelHistory*> run_history_by_locomotive(
    const std::vector<host::WheelHistory>& histories) {
  std::map<std::string, const host::WheelHistory*> by_locomotive;
  for (const host::WheelHistory& history : histories) {
    const host::WheelHistory*& kept = by_locomotive[history.wheel.locomotive];
    if (kept == nullptr || history.runs.size() > kept->runs.size()) kept = &history;
  }
  return by_locomotive;
}

void check_names(const sim::FleetTruth& truth,
                 const std::map<std::string, const host::WheelHistory*>& stored,
                 const std::string& file) {
  std::set<std::string> named;
  for (const sim::LocomotiveTruth& loco : truth.locomotives) named.insert(loco.name);
  for (const auto& [name, history] : stored) {
    if (named.count(name) == 0) {
      another_fleet(file, fmt::format("the store's locomotive {} is not in it",
                                      host::printable_excerpt(name)));
    }
  }
  for (const std::string& name : named) {
    if (stored.count(name) == 0) {
      another_fleet(file, fmt::format("its locomotive {} has no run in the store",
                                      host::printable_excerpt(name)));
    }
  }
}

// Every run on one of the truth's days, and the odometer's steps its days' distances.
void check_runs(const sim::LocomotiveTruth& loco, const host::WheelHistory& history, int start_day,
                const std::string& file) {
  const int days = static_cast<int>(loco.day_km.size());
  std::vector<double> through(loco.day_km.size() + 1, 0.0);  // km run by the end of day d - 1
  for (int d = 0; d < days; ++d) through[d + 1] = through[d] + loco.day_km[d];
  int steps = 0, off = 0;
  for (std::size_t k = 0; k < history.runs.size(); ++k) {
    const host::WearObservation& run = history.runs[k];
    const int day = static_cast<int>(std::floor(run.day)) - start_day;
    if (day < 0 || day >= days) {
      another_fleet(file, fmt::format("{}'s run at {} is outside its days {} to {}", loco.name,
                                      host::printable_excerpt(run.at), host::date_of_day(start_day),
                                      host::date_of_day(start_day + days - 1)));
    }
    if (k == 0) continue;
    const int before = static_cast<int>(std::floor(history.runs[k - 1].day)) - start_day;
    // The fleet scenario stores the day's start reading plus the recording's own distance (the
    // same each run): between two runs the odometer moves by the days from the first to the
    // day before the second. A reading taken at the day's end moves by the days after the first
    // to the second. Either is this fleet's.
    const double stored_km = run.odometer_km - history.runs[k - 1].odometer_km;
    const bool matches =
        std::abs(stored_km - (through[day] - through[before])) <= kOdometerToleranceKm ||
        std::abs(stored_km - (through[day + 1] - through[before + 1])) <= kOdometerToleranceKm;
    ++steps;
    if (!matches) ++off;
  }
  if (2 * off > steps) {
    another_fleet(file, fmt::format("{}'s odometer steps between runs are not its days' "
                                    "distances ({} of {} differ by more than {:g} km)",
                                    loco.name, off, steps, kOdometerToleranceKm));
  }
}

}  // namespace

void check_truth_matches_runs(const sim::FleetTruth& truth,
                              const std::vector<host::WheelHistory>& histories,
                              const std::string& file) {
  const auto stored = run_history_by_locomotive(histories);
  check_names(truth, stored, file);
  for (const sim::LocomotiveTruth& loco : truth.locomotives) {
    check_runs(loco, *stored.at(loco.name), truth.settings.start_day, file);
  }
}

}  // namespace flange::cli
