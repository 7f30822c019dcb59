// SPDX-License-Identifier: MIT
// `flange diagnose --hw`: the command line of diagnose/hw (the float design of a coefficient set
// against its Verilated RTL, or against printed coefficients, the gap attributed to the
// fixed-point effects step by step).
//
// Merging with the other `diagnose` layers: add_hw_diagnose_options adds the options only the
// hardware layer has; add_hw_diagnose_shared_options adds --seed and --out, which the data layer
// and --selftest may declare too (then bind theirs to the same fields instead).
#pragma once

#include <CLI/CLI.hpp>
#include <filesystem>
#include <iosfwd>
#include <optional>

#include "hw_diagnosis.h"

namespace flange::cli {

struct HwDiagnoseOptions {
  bool hw = false;  // --hw: run this layer
  diagnose::HwRequest request;
  std::optional<std::filesystem::path> out;  // folder for the JSON, HTML and SVG files
};

// --hw --coeffs --stimulus --samples --thesis-eq-4-20 --tf-b --tf-a
void add_hw_diagnose_options(CLI::App& diagnose, HwDiagnoseOptions& options);
// --seed --out
void add_hw_diagnose_shared_options(CLI::App& diagnose, HwDiagnoseOptions& options);

// Prints the step table and one final line on `out`. Returns 0 when the gap is explained (zero
// after the last step; staged model = bit-accurate model = RTL word for word) or, in printed mode,
// when the diagnosis is made (unstable or not); 1 when the RTL disagrees. Throws when the RTL
// cannot be built or a file cannot be written (1) and on bad input (2: host::InputError or
// std::invalid_argument, one line naming the option or file and field).
int run_hw_diagnosis(const HwDiagnoseOptions& options, std::ostream& out, std::ostream& err);

}  // namespace flange::cli
