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
  // --plan: the wheels to reprofile before `before` at `risk` (host/wear/reprofiling_plan.h),
  // as OUT/plan.csv (or `plan_csv`; "-" for stdout) and a section of the wear page.
  bool plan = false;
  std::string before;  // YYYY-MM-DD, after the last run
  double risk = 0.05;  // in (0, 1)
  std::optional<std::string> plan_csv;
};

CLI::App* add_wear_command(CLI::App& app, WearOptions& options);

// Returns 0, or 1 when the comparison with --truth fails. Throws when the store cannot be read,
// does not exist or holds no run, or an output cannot be written (1), and for a bad argument (2:
// one line naming it and its valid range: a --risk outside (0, 1), a --before not after the last
// run, a --truth file of another fleet). Nothing is written when it exits 2, or 1 before the
// estimate.
int run_wear_command(const WearOptions& options, const std::vector<std::string>& command_line,
                     std::ostream& out, std::ostream& err);

}  // namespace flange::cli
