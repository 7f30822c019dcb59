// SPDX-License-Identifier: MIT
// `flange simulate --scenario fleet`: a depot's locomotives over days (sim/src/fleet_plan.h),
// each day's twelve recordings through the chain `flange run --manifest` runs (calibration,
// filter, alarms) into the store, with each axle's static clearance at reference conditions
// (host/wear/axle_clearance.h) as the run's per-wheel wear estimate; the depot's reprofilings
// as maintenance events; the truth in a file beside the store.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "simulate_command.h"

namespace flange::cli {

// Returns 0; throws when the store or a file cannot be written (1) and for a bad argument (2:
// one line naming the option and its valid range; a store URL's with --store before it).
int run_fleet_simulation(const SimulateOptions& options,
                         const std::vector<std::string>& command_line, std::ostream& out);

}  // namespace flange::cli
