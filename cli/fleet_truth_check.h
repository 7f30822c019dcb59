// SPDX-License-Identifier: MIT
// `flange wear --truth FILE`: the estimate against the fleet scenario's truth. A wheel's rate
// passes when it is within kRateTolerance of the truth or the truth lies inside its 95 %
// interval; every reprofiling the data can show (one with a run after it) must be found in the
// data (not only read from the depot's record); every drifting sensor flagged, no healthy one.
//
// And how often the intervals hold: per wheel, whether the true rate lies in its interval at
// each of kCoverageLevels, and whether the true dates of the warning and the critical limit do.
// A true date is the day the wheel's true wear, going on at its true rate from its last run over
// the km its locomotive runs after the period (the scenario's own draws of those days, without a
// reprofiling), reaches the limit; it is known when the truth file is the fleet scenario's (its
// days replanned from its seed give its km), or when the file states its own dates for the
// estimate's limits (the second reality's: sim/fleet_alt/fleet_alt_limits.h).
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "fleet_plan.h"
#include "fleet_wear.h"

namespace flange::cli {

inline constexpr double kRateTolerance = 0.10;  // the relative error a rate may have
// The levels the intervals are checked at: the one printed and one further in.
inline constexpr std::array<double, 2> kCoverageLevels{0.95, 0.80};

// Whether a truth lies in an interval, at each of kCoverageLevels; `known` false when there is
// nothing to check (no rate fitted, a date without its truth).
struct Coverage {
  bool known = false;
  std::array<bool, kCoverageLevels.size()> held{};
};

struct WheelCheck {
  std::string locomotive;
  int axle = 0;
  std::string side;
  double true_rate = 0.0;  // mm per 1000 km
  double rate = 0.0, rate_low = 0.0, rate_high = 0.0;
  double relative_error = 0.0;
  bool rate_ok = false;
  int true_reprofilings = 0;   // with a run after them
  int found_reprofilings = 0;  // of those, found in the data
  bool drifting = false;       // the truth
  bool flagged = false;  // the estimate: this search, a flag latched by earlier ones, or "sensor fault"
  bool latched = false;        // a sensor flag confirmed by earlier estimates (still held)
  std::string kind;            // "healthy", "reprofiled" (with a run after it) or "drifting sensor"
  Coverage rate_coverage, warning_coverage, critical_coverage;
  std::optional<int> true_warning_day, true_critical_day;  // days since 1970-01-01
};

struct TruthCheck {
  std::vector<WheelCheck> wheels;  // by locomotive, axle, side
  int rates_ok = 0;
  int reprofilings = 0, reprofilings_found = 0;
  int drifting = 0, drifting_flagged = 0, healthy_flagged = 0;
  double max_relative_error = 0.0;
  bool passed() const;
};

TruthCheck check_against_truth(const host::FleetWear& wear, const sim::FleetTruth& truth);

// The coverage table: per wheel kind and quantity, how many intervals at each level hold.
std::string coverage_text(const TruthCheck& check);

// The table (Markdown, as in docs/fleet.md), the verdict line and the coverage table.
std::string truth_check_text(const TruthCheck& check);

void write_truth_check_json(const std::filesystem::path& path, const TruthCheck& check);

}  // namespace flange::cli
