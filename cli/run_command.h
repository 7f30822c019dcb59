// SPDX-License-Identifier: MIT
// `flange run`: a recording through regression, filter and thresholds, with a summary, an
// output CSV and an HTML report.
#pragma once

#include <CLI/CLI.hpp>
#include <iosfwd>

#include "run_pipeline.h"

namespace flange::cli {

CLI::App* add_run_command(CLI::App& app, host::RunOptions& options);
int run_run_command(const host::RunOptions& options, std::ostream& out, std::ostream& err);

}  // namespace flange::cli
