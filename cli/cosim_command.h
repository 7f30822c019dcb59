// SPDX-License-Identifier: MIT
// `flange cosim`: streams a stimulus through the Verilated iir_core of a coefficient set and the
// bit-accurate model, compares every pin in every cycle, and ends with one summary line.
#pragma once

#include <CLI/CLI.hpp>
#include <iosfwd>

#include "cosim_run.h"

namespace flange::cli {

struct CosimCommandOptions {
  tb::CosimOptions run;  // --coeffs --samples --seed --stimulus --trace
};

CLI::App* add_cosim_command(CLI::App& app, CosimCommandOptions& options);

// The RTL is Verilated per coefficient set (its package differs), so the first run for a set
// builds a runner with Verilator (about 15 s) into a cache folder keyed by the content of the RTL,
// the set's package and ROM image and the runner's sources (tb/runner/verilated_runner.h says
// where). Returns the runner's status (0, or 1 after the first mismatch); throws for bad input
// (2) and for a runner that cannot be built or started (1).
int run_cosim_command(const CosimCommandOptions& options, std::ostream& out, std::ostream& err);

}  // namespace flange::cli
