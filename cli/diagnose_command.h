// SPDX-License-Identifier: MIT
// `flange diagnose --real`: the command line of diagnose/data (the sim-to-real gap of a recording,
// docs/diagnose.md). Writes DIR/diagnosis.json and DIR/report.html and prints a summary whose
// first line is the verdict. --selftest and --hw are separate modes added beside this one.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>

namespace flange::cli {

struct DiagnoseCommandOptions {
  std::string real;                        // recording CSV (required for the data layer)
  std::optional<std::string> holdout;      // a separate held-out recording ...
  std::optional<double> holdout_fraction;  // ... or the last fraction of `real`, [0.05, 0.5]
  // When each session's t_s = 0 was (ISO 8601 UTC), for a separate held-out recording.
  std::optional<std::string> real_start, holdout_start;
  std::optional<std::string> twin;         // twin.json; default: nominal eq. 3.14
  std::string out;                         // output folder
  std::uint64_t seed = 1;
  int bootstrap_rounds = 100;
};

CLI::App* add_diagnose_command(CLI::App& app, DiagnoseCommandOptions& options);

// Returns 0; throws host::InputError or sim::BadArgument for a bad recording, option or twin
// file (2) and std::runtime_error for an output that cannot be written (1).
int run_diagnose_command(const DiagnoseCommandOptions& options, std::ostream& out);

}  // namespace flange::cli
