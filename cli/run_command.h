// SPDX-License-Identifier: MIT
// `flange run`: a recording (or every channel of a locomotive's manifest) through regression,
// filter and thresholds, with a summary, output CSVs and an HTML report.
#pragma once

#include <CLI/CLI.hpp>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "run_pipeline.h"

namespace flange::cli {

struct RunCommandOptions {
  host::RunOptions run;                 // --input's run; with --manifest, shared by every channel
  std::optional<std::string> manifest;  // locomotive.json: run every channel it names
};

CLI::App* add_run_command(CLI::App& app, RunCommandOptions& options);

// Returns 0, 1 (a file could not be written, or the RTL disagreed with the model) or 2 (bad
// input: one line names the file, line or field and the valid range). `command_line` is
// recorded in a manifest run's summary.json.
int run_run_command(const RunCommandOptions& options, const std::vector<std::string>& command_line,
                    std::ostream& out, std::ostream& err);

}  // namespace flange::cli
