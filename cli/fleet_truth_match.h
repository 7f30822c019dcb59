// SPDX-License-Identifier: MIT
// `flange wear --truth FILE`: is FILE the truth of the fleet in the store? Its locomotives must
// be the store's, every run must fall on one of its days, and each locomotive's odometer must
// advance between runs by the distances the truth gives its days, read at the day's start or
// its end (most steps within kOdometerToleranceKm: an odometer reset moves one step, another
// fleet nearly all).
#pragma once

#include <string>
#include <vector>

#include "fleet_plan.h"
#include "wheel_history.h"

namespace flange::cli {

inline constexpr double kOdometerToleranceKm = 1.0;  // the odometer is stored to well under it

// Throws host::InputError (exit status 2), one line naming `file` and what differs, when the
// truth is of another fleet.
void check_truth_matches_runs(const sim::FleetTruth& truth,
                              const std::vector<host::WheelHistory>& histories,
                              const std::string& file);

}  // namespace flange::cli
