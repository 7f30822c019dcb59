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

// Returns 0 or 1 (the RTL disagreed with the model); throws for a file that cannot be written
// or a store that cannot be opened or written (1), and host::InputError or host::StoreUrlError
// for bad input or a malformed store URL (2: one line names the file, line or field and the
// valid range). `command_line` is recorded in a manifest run's summary.json.
int run_run_command(const RunCommandOptions& options, const std::vector<std::string>& command_line,
                    std::ostream& out);

}  // namespace flange::cli
