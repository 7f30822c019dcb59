// SPDX-License-Identifier: MIT
// `flange diagnose --hw`: the hardware layer of the sim-to-real diagnosis. The float design of a
// coefficient set is the sim, the Verilated RTL is the real; the gap between them on a stimulus is
// attributed by adding the fixed-point effects one at a time to the float model, greedily, down to
// zero (host/src/hw_gap.h). With --thesis-eq-4-20 (or --tf-b/--tf-a) the real is a printed set of
// direct-form coefficients instead, and the diagnosis says whether rounding to them alone makes
// the filter unstable.
//
// Merging with the other `diagnose` layers: add_hw_diagnose_options adds the options only the
// hardware layer has; add_hw_diagnose_shared_options adds --seed and --out, which the data layer
// and --selftest may declare too (then bind theirs to the same fields instead).
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace flange::host {

struct HwDiagnoseOptions {
  bool hw = false;                  // --hw: run this layer
  std::filesystem::path coeffs;     // --coeffs: filter.json of a coefficient set (required)
  std::string stimulus = "random";  // random|fullscale|sweep|step|impulse|FILE.csv
  std::size_t samples = 10000;      // 1..10^7
  std::uint64_t seed = 1;           // random and fullscale stimuli
  std::optional<std::filesystem::path> out;  // folder for the JSON, HTML and SVG files
  bool thesis_eq_4_20 = false;               // the printed eq. 4.20 coefficients against --coeffs
  std::vector<double> tf_b, tf_a;            // printed direct-form coefficients against --coeffs
};

// --hw --coeffs --stimulus --samples --thesis-eq-4-20 --tf-b --tf-a
void add_hw_diagnose_options(CLI::App& diagnose, HwDiagnoseOptions& options);
// --seed --out
void add_hw_diagnose_shared_options(CLI::App& diagnose, HwDiagnoseOptions& options);

// Prints the step table and one final line on `out`. Returns 0 when the gap is explained (zero
// after the last step; staged model = bit-accurate model = RTL word for word) or, in printed mode,
// when the diagnosis is made (unstable or not); 1 when the RTL disagrees or cannot be built, or a
// file cannot be written; 2 on bad input (one line on `err` naming the option or file and field).
int run_hw_diagnosis(const HwDiagnoseOptions& options, std::ostream& out, std::ostream& err);

}  // namespace flange::host
