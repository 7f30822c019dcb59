// SPDX-License-Identifier: MIT
// `flange diagnose --selftest --cases N --seed S`: the blind check of the data layer
// (diagnose/data/selftest/diagnose_selftest.h). Prints one row per case and the summary against the aims;
// with --out writes DIR/selftest.json and DIR/selftest.md (as docs/diagnose_figures.md records
// it). `--reality alt [--pairs N]` runs it on the alternative reality instead
// (diagnose/alt_check/, diagnose_alt_selftest_command.h), `--reality third` on the third
// (diagnose_third_selftest_command.h).
#pragma once

#include <CLI/CLI.hpp>
#include <iosfwd>
#include <optional>
#include <string>

#include "diagnose_selftest.h"

namespace flange::cli {

struct SelftestCommandOptions {
  bool selftest = false;
  diagnose::SelftestOptions run;   // cases, duration, jobs; seed and bootstrap from the data layer
  std::string reality = "twin";    // "twin": the sensor twin's sessions; "alt": the alternative
                                   // reality's; "third": the third reality's
  std::optional<std::string> out;  // folder for selftest.json and selftest.md
};

// --selftest --reality --cases (--pairs) --case --duration --jobs (--seed, --out and --bootstrap
// are the data layer's).
void add_selftest_options(CLI::App& diagnose, SelftestCommandOptions& options);

// 0 when every aim is met, 1 when one is missed (the summary says which); throws
// std::runtime_error when a file cannot be written (1) and host::InputError on a bad argument (2).
int run_selftest_command(const SelftestCommandOptions& options, std::ostream& out);

}  // namespace flange::cli
