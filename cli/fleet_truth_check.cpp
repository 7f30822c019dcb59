// SPDX-License-Identifier: MIT
#include "fleet_truth_check.h"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
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
  check.flagged = w->sensor_fault.has_value();
  count_reprofilings(check, *w, wheel.reprofiled_days, truth.settings.start_day);
  return check;
}

}  // namespace

bool TruthCheck::passed() const {
  return rates_ok == static_cast<int>(wheels.size()) && reprofilings_found == reprofilings &&
         drifting_flagged == drifting && healthy_flagged == 0;
}

TruthCheck check_against_truth(const host::FleetWear& wear, const sim::FleetTruth& truth) {
  TruthCheck result;
  for (std::size_t l = 0; l < truth.locomotives.size(); ++l) {
    for (const sim::WheelTruth& wheel : truth.locomotives[l].wheels) {
      const sim::WheelPosition position = sim::wheel_position(wheel.channel);
      const host::WheelWear* w =
          find_wheel(wear, truth.locomotives[l].name, position.axle, sim::side_name(position.side));
      const WheelCheck check = check_wheel(w, truth, static_cast<int>(l), wheel);
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
  return text;
}

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
                      {"flagged", w.flagged}});
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
