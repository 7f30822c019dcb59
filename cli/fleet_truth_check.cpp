// SPDX-License-Identifier: MIT
#include "fleet_truth_check.h"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "limit_forecast.h"
#include "locomotive_wheels.h"

namespace flange::cli {
namespace {

const host::WheelWear* find_wheel(const host::FleetWear& wear, const std::string& loco, int axle,
                                  const std::string& side) {
  for (const host::WheelWear& w : wear.wheels) {
    if (w.wheel.locomotive == loco && w.wheel.axle == axle && w.wheel.side == side) return &w;
  }
  return nullptr;
}

// Reprofilings on `day` (from the truth's first day) that the wheel's runs straddle, and of
// those how many the data showed.
void count_reprofilings(WheelCheck& check, const host::WheelWear& w, const std::vector<int>& days,
                        int start_day) {
  for (const int day : days) {
    const double at = start_day + day;
    if (w.runs.empty() || w.runs.back().day <= at || w.runs.front().day >= at) continue;
    ++check.true_reprofilings;
    for (const host::ReprofilingEvent& event : w.reprofilings) {
      if (event.found && host::day_of_iso_time(event.last_run_before) < at &&
          host::day_of_iso_time(event.first_run_after) > at) {
        ++check.found_reprofilings;
        break;
      }
    }
  }
}

// The fleet's days after the period, drawn again from its seed; nothing when the truth is not
// the fleet scenario's (its km differ from the redrawn ones).
std::optional<sim::FleetTruth> future_of(const sim::FleetTruth& truth) {
  sim::FleetSettings settings = truth.settings;
  settings.locomotives = static_cast<int>(truth.locomotives.size());
  settings.days = sim::kMaxFleetDays;
  if (settings.locomotives < 1 || settings.locomotives > sim::kMaxFleetLocomotives ||
      truth.settings.days > settings.days) {
    return std::nullopt;
  }
  sim::FleetTruth future = sim::plan_fleet(settings);
  for (std::size_t l = 0; l < truth.locomotives.size(); ++l) {
    const std::vector<double>& known = truth.locomotives[l].day_km;
    const std::vector<double>& redrawn = future.locomotives[l].day_km;
    for (std::size_t d = 0; d < known.size(); ++d) {
      if (std::abs(known[d] - redrawn[d]) > 1e-6 * std::max(1.0, known[d])) return std::nullopt;
    }
  }
  return future;
}

// The day (since 1970-01-01) on which the wheel's true wear, from the start of `first` (days
// from the truth's first day) on at its true rate without a reprofiling, reaches `limit_wear_mm`.
std::optional<int> true_limit_day(const sim::FleetTruth& future, int l, int channel, int first,
                                  double limit_wear_mm) {
  const sim::LocomotiveTruth& loco = future.locomotives[static_cast<std::size_t>(l)];
  const auto c = static_cast<std::size_t>(channel);
  const double rate = loco.wheels[c].wear_rate_mm_per_1000km / 1000.0;
  double wear = loco.wear_mm.at(static_cast<std::size_t>(first))[c];
  if (wear >= limit_wear_mm) return future.settings.start_day + first;
  for (auto d = static_cast<std::size_t>(first); d < loco.day_km.size(); ++d) {
    wear += rate * loco.day_km[d];  // reached in the day's service
    if (wear >= limit_wear_mm) return future.settings.start_day + static_cast<int>(d);
  }
  return std::nullopt;
}

Coverage rate_coverage(const host::WheelWear& w, double true_rate) {
  Coverage coverage;
  coverage.known = w.fit.has_value();
  for (std::size_t i = 0; i < kCoverageLevels.size(); ++i) {
    const auto [low, high] = host::rate_interval(w, kCoverageLevels[i]);
    coverage.held[i] = true_rate >= low && true_rate <= high;
  }
  return coverage;
}

// Whether the true day lies in the forecast's interval of days at each level (a day past the
// redrawn future only in an interval open at its slow end or reaching past it).
Coverage date_coverage(const host::WheelWear& w, double limit_clearance_mm,
                       std::optional<int> true_day, double horizon_day) {
  Coverage coverage;
  coverage.known = w.fit.has_value();
  const double last = std::floor(w.runs.back().day);
  for (std::size_t i = 0; i < kCoverageLevels.size(); ++i) {
    const host::LimitForecast f =
        host::forecast_limit(w.forecast_input, limit_clearance_mm, kCoverageLevels[i]);
    const double truth = true_day ? *true_day : horizon_day;
    if (f.reached) {
      coverage.held[i] = truth <= last;
    } else if (f.days_low) {
      const double low = std::floor(w.runs.back().day + *f.days_low);
      const double high = f.days_high ? std::floor(w.runs.back().day + *f.days_high)
                                      : std::numeric_limits<double>::infinity();
      coverage.held[i] = truth >= low && (truth <= high || (!true_day && high >= horizon_day));
    }
  }
  return coverage;
}

void check_dates(WheelCheck& check, const host::WheelWear& w, const host::FleetWear& wear,
                 const sim::FleetTruth& future, int l, int channel) {
  const int first = static_cast<int>(std::floor(w.runs.back().day)) - future.settings.start_day;
  const double gap = wear.thresholds.sensor_gap_mm;
  check.true_warning_day =
      true_limit_day(future, l, channel, first, wear.warning_clearance_mm - gap);
  check.true_critical_day =
      true_limit_day(future, l, channel, first, wear.critical_clearance_mm - gap);
  const double horizon = future.settings.start_day + future.settings.days;
  check.warning_coverage =
      date_coverage(w, wear.warning_clearance_mm, check.true_warning_day, horizon);
  check.critical_coverage =
      date_coverage(w, wear.critical_clearance_mm, check.true_critical_day, horizon);
}

// A truth file's own dates (another reality's), when they are for the estimate's limits.
void check_stated_dates(WheelCheck& check, const host::WheelWear& w, const host::FleetWear& wear,
                        const sim::FleetTruth& truth, const sim::WheelTruth& wheel) {
  const sim::TruthLimitDates& limits = *truth.limit_dates;
  const int start = truth.settings.start_day;
  const auto day = [&](const std::optional<int>& offset) -> std::optional<int> {
    return offset ? std::optional(start + *offset) : std::nullopt;
  };
  const double horizon = start + limits.horizon_days;
  constexpr double kSameMm = 1e-9;
  if (std::abs(limits.warning_clearance_mm - wear.warning_clearance_mm) < kSameMm) {
    check.true_warning_day = day(wheel.warning_day);
    check.warning_coverage =
        date_coverage(w, wear.warning_clearance_mm, check.true_warning_day, horizon);
  }
  if (std::abs(limits.critical_clearance_mm - wear.critical_clearance_mm) < kSameMm) {
    check.true_critical_day = day(wheel.critical_day);
    check.critical_coverage =
        date_coverage(w, wear.critical_clearance_mm, check.true_critical_day, horizon);
  }
}

WheelCheck check_wheel(const host::WheelWear* w, const sim::FleetTruth& truth, int l,
                       const sim::WheelTruth& wheel) {
  const sim::WheelPosition position = sim::wheel_position(wheel.channel);
  WheelCheck check;
  check.locomotive = truth.locomotives[static_cast<std::size_t>(l)].name;
  check.axle = position.axle;
  check.side = sim::side_name(position.side);
  check.true_rate = wheel.wear_rate_mm_per_1000km;
  check.drifting = sim::drift_of(truth, l, wheel.channel) != nullptr;
  if (w == nullptr) return check;
  check.rate = w->rate_mm_per_1000km;
  check.rate_low = w->rate_low;
  check.rate_high = w->rate_high;
  check.relative_error = (check.rate - check.true_rate) / check.true_rate;
  check.rate_ok =
      w->fit && (std::abs(check.relative_error) <= kRateTolerance ||
                 (check.true_rate >= check.rate_low && check.true_rate <= check.rate_high));
  check.latched = w->sensor_flag && w->sensor_flag->latched();
  // Flagged: the page calls the sensor faulty, by this estimate's drift search, a flag the latch
  // kept, or a rate that cannot be told from no wear whose cause is a drift (negative_rate.h).
  check.flagged = w->sensor_fault.has_value() || check.latched || w->status == "sensor fault";
  count_reprofilings(check, *w, wheel.reprofiled_days, truth.settings.start_day);
  check.kind = check.drifting                ? "drifting sensor"
               : check.true_reprofilings > 0 ? "reprofiled"
                                             : "healthy";
  check.rate_coverage = rate_coverage(*w, check.true_rate);
  return check;
}

}  // namespace

bool TruthCheck::passed() const {
  return rates_ok == static_cast<int>(wheels.size()) && reprofilings_found == reprofilings &&
         drifting_flagged == drifting && healthy_flagged == 0;
}

TruthCheck check_against_truth(const host::FleetWear& wear, const sim::FleetTruth& truth) {
  TruthCheck result;
  const std::optional<sim::FleetTruth> future = future_of(truth);
  for (std::size_t l = 0; l < truth.locomotives.size(); ++l) {
    for (const sim::WheelTruth& wheel : truth.locomotives[l].wheels) {
      const sim::WheelPosition position = sim::wheel_position(wheel.channel);
      const host::WheelWear* w =
          find_wheel(wear, truth.locomotives[l].name, position.axle, sim::side_name(position.side));
      WheelCheck check = check_wheel(w, truth, static_cast<int>(l), wheel);
      if (w != nullptr && w->fit && future) {
        check_dates(check, *w, wear, *future, static_cast<int>(l), wheel.channel);
      } else if (w != nullptr && w->fit && truth.limit_dates) {
        check_stated_dates(check, *w, wear, truth, wheel);
      }
      result.rates_ok += check.rate_ok ? 1 : 0;
      result.reprofilings += check.true_reprofilings;
      result.reprofilings_found += check.found_reprofilings;
      result.drifting += check.drifting ? 1 : 0;
      result.drifting_flagged += check.drifting && check.flagged ? 1 : 0;
      result.healthy_flagged += !check.drifting && check.flagged ? 1 : 0;
      result.max_relative_error =
          std::max(result.max_relative_error, std::abs(check.relative_error));
      result.wheels.push_back(check);
    }
  }
  return result;
}

namespace {

constexpr std::array<const char*, 3> kKinds{"healthy", "reprofiled", "drifting sensor"};

struct CoverageCount {
  int checked = 0;
  std::array<int, kCoverageLevels.size()> held{};
  void add(const Coverage& c) {
    if (!c.known) return;
    ++checked;
    for (std::size_t i = 0; i < held.size(); ++i) held[i] += c.held[i] ? 1 : 0;
  }
};

// Per kind ("all" last) the counts of the rate, warning and critical intervals.
std::vector<std::pair<std::string, std::array<CoverageCount, 3>>> coverage_counts(
    const TruthCheck& check) {
  std::vector<std::pair<std::string, std::array<CoverageCount, 3>>> rows;
  for (const char* kind : kKinds) rows.push_back({kind, {}});
  rows.push_back({"all", {}});
  for (const WheelCheck& w : check.wheels) {
    for (auto& [kind, counts] : rows) {
      if (kind != "all" && kind != w.kind) continue;
      counts[0].add(w.rate_coverage);
      counts[1].add(w.warning_coverage);
      counts[2].add(w.critical_coverage);
    }
  }
  return rows;
}

std::string held_text(const CoverageCount& count, std::size_t level) {
  if (count.checked == 0) return "-";
  return fmt::format("{} ({:.1f} %)", count.held[level], 100.0 * count.held[level] / count.checked);
}

}  // namespace

std::string coverage_text(const TruthCheck& check) {
  std::string text =
      "| wheels | interval of | checked | holds the truth at 95 % | at 80 % |\n"
      "|---|---|---|---|---|\n";
  constexpr std::array<const char*, 3> kQuantities{"rate", "warning date", "critical date"};
  for (const auto& [kind, counts] : coverage_counts(check)) {
    for (std::size_t q = 0; q < kQuantities.size(); ++q) {
      text += fmt::format("| {} | {} | {} | {} | {} |\n", kind, kQuantities[q], counts[q].checked,
                          held_text(counts[q], 0), held_text(counts[q], 1));
    }
  }
  return text;
}

std::string truth_check_text(const TruthCheck& check) {
  std::string text =
      "| locomotive | wheel | true rate | estimated rate [95 %] | error | rate ok | "
      "reprofilings found / true | drifting (truth) | flagged |\n"
      "|---|---|---|---|---|---|---|---|---|\n";
  for (const WheelCheck& w : check.wheels) {
    text += fmt::format(
        "| {} | axle {} {} | {:.4f} | {:.4f} [{:.4f}, {:.4f}] | {:+.1f} % | {} | {} / {} | {} | "
        "{} |\n",
        w.locomotive, w.axle, w.side, w.true_rate, w.rate, w.rate_low, w.rate_high,
        100.0 * w.relative_error, w.rate_ok ? "yes" : "**no**", w.found_reprofilings,
        w.true_reprofilings, w.drifting ? "drifting" : "-", w.flagged ? "flagged" : "-");
  }
  text += fmt::format(
      "\nrates within {:.0f} % or inside the interval: {} of {} (largest error {:.1f} %); "
      "reprofilings found: {} of {}; drifting sensors flagged: {} of {}; healthy sensors "
      "flagged: {}\nverdict: {}\n",
      100.0 * kRateTolerance, check.rates_ok, check.wheels.size(), 100.0 * check.max_relative_error,
      check.reprofilings_found, check.reprofilings, check.drifting_flagged, check.drifting,
      check.healthy_flagged, check.passed() ? "pass" : "FAIL");
  text += "\nhow often the intervals hold the truth:\n\n" + coverage_text(check);
  return text;
}

namespace {

// {"95": true, "80": false}, or null when there was nothing to check.
nlohmann::ordered_json coverage_json(const Coverage& coverage) {
  if (!coverage.known) return nullptr;
  nlohmann::ordered_json json;
  for (std::size_t i = 0; i < kCoverageLevels.size(); ++i) {
    json[fmt::format("{:.0f}", 100.0 * kCoverageLevels[i])] = coverage.held[i];
  }
  return json;
}

nlohmann::ordered_json day_json(const std::optional<int>& day) {
  return day ? nlohmann::ordered_json(host::date_of_day(*day)) : nlohmann::ordered_json(nullptr);
}

}  // namespace

void write_truth_check_json(const std::filesystem::path& path, const TruthCheck& check) {
  nlohmann::ordered_json wheels = nlohmann::ordered_json::array();
  for (const WheelCheck& w : check.wheels) {
    wheels.push_back({{"locomotive", w.locomotive},
                      {"axle", w.axle},
                      {"side", w.side},
                      {"true_rate", w.true_rate},
                      {"rate", w.rate},
                      {"rate_low", w.rate_low},
                      {"rate_high", w.rate_high},
                      {"relative_error", w.relative_error},
                      {"rate_ok", w.rate_ok},
                      {"true_reprofilings", w.true_reprofilings},
                      {"found_reprofilings", w.found_reprofilings},
                      {"drifting", w.drifting},
                      {"flagged", w.flagged},
                      {"latched", w.latched},
                      {"kind", w.kind},
                      {"rate_coverage", coverage_json(w.rate_coverage)},
                      {"true_warning_date", day_json(w.true_warning_day)},
                      {"warning_coverage", coverage_json(w.warning_coverage)},
                      {"true_critical_date", day_json(w.true_critical_day)},
                      {"critical_coverage", coverage_json(w.critical_coverage)}});
  }
  const nlohmann::ordered_json json = {{"passed", check.passed()},
                                       {"rates_ok", check.rates_ok},
                                       {"wheels_checked", check.wheels.size()},
                                       {"max_relative_error", check.max_relative_error},
                                       {"reprofilings", check.reprofilings},
                                       {"reprofilings_found", check.reprofilings_found},
                                       {"drifting", check.drifting},
                                       {"drifting_flagged", check.drifting_flagged},
                                       {"healthy_flagged", check.healthy_flagged},
                                       {"wheels", wheels}};
  std::ofstream file(path, std::ios::binary);
  file << json.dump(1) << "\n";
  if (!file) throw std::runtime_error(path.string() + ": cannot write");
}

}  // namespace flange::cli
