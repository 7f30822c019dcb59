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

// Returns 0; throws std::runtime_error when a file cannot be written (1) and
// std::invalid_argument for a bad argument (2: one line naming the option and its valid range).
int run_fleet_alt_simulation(const SimulateOptions& options,
                             const std::vector<std::string>& command_line, std::ostream& out);

}  // namespace flange::cli
