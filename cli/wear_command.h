// SPDX-License-Identifier: MIT
// The `flange wear` subcommand: every wheel's wear over the runs in a store, its rate, its
// reprofilings, its sensor's health and when it reaches the flange limits (docs/fleet.md).
#pragma once

#include <CLI/CLI.hpp>
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "thresholds.h"

namespace flange::cli {

struct WearOptions {
  std::string store;  // sqlite:PATH or postgresql://...
  std::filesystem::path out;
  std::optional<std::filesystem::path> truth;  // a fleet scenario's truth file to compare with
  host::ThresholdConfig thresholds;            // the alarm settings the limits come from
};

CLI::App* add_wear_command(CLI::App& app, WearOptions& options);

// Returns 0; 1 when the store cannot be read or an output written, or when the comparison with
// --truth fails; 2 for a bad argument (one line naming it and its valid range).
int run_wear_command(const WearOptions& options, const std::vector<std::string>& command_line,
                     std::ostream& out, std::ostream& err);

}  // namespace flange::cli
