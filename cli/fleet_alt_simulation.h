// SPDX-License-Identifier: MIT
// `flange simulate --scenario fleet-alt --out DIR`: the second fleet reality
// (sim/fleet_alt/README.md) written as a depot hands it to the service path: bench sessions,
// every recorded locomotive-day's manifest and recordings, runs.csv, maintenance.csv and the
// truth (docs/fleet.md, "A second fleet reality").
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "simulate_command.h"

namespace flange::cli {

// Returns 0, 1 (a file cannot be written) or 2 (a bad argument: one line naming the option and
// its valid range).
int run_fleet_alt_simulation(const SimulateOptions& options,
                             const std::vector<std::string>& command_line, std::ostream& out,
                             std::ostream& err);

}  // namespace flange::cli
