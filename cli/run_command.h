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
#include "run_store.h"

namespace flange::cli {

struct RunCommandOptions {
  host::RunOptions run;                 // --input's run; with --manifest, shared by every channel
  std::optional<std::string> manifest;  // locomotive.json: run every channel it names
  RunStoreOptions store;                // --store and what the store records about the run
};

CLI::App* add_run_command(CLI::App& app, RunCommandOptions& options);

// Returns 0, 1 (a file could not be written, the RTL disagreed with the model, or the store
// cannot be opened or written) or 2 (bad input or a malformed store URL: one line names the
// file, line or field and the valid range). `command_line` is
// recorded in a manifest run's summary.json.
int run_run_command(const RunCommandOptions& options, const std::vector<std::string>& command_line,
                    std::ostream& out, std::ostream& err);

}  // namespace flange::cli
