// SPDX-License-Identifier: MIT
// `flange wear --truth FILE`: the estimate against the fleet scenario's truth. A wheel's rate
// passes when it is within kRateTolerance of the truth or the truth lies inside its 95 %
// interval; every reprofiling the data can show (one with a run after it) must be found in the
// data (not only read from the depot's record); every drifting sensor flagged, no healthy one.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "fleet_plan.h"
#include "fleet_wear.h"

namespace flange::cli {

inline constexpr double kRateTolerance = 0.10;  // the relative error a rate may have

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
  bool flagged = false;        // the estimate
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

// The table (Markdown, as in docs/fleet.md) and the verdict line.
std::string truth_check_text(const TruthCheck& check);

void write_truth_check_json(const std::filesystem::path& path, const TruthCheck& check);

}  // namespace flange::cli
