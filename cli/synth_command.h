// SPDX-License-Identifier: MIT
// `flange synth`: the command line of tb/synth (Yosys on the core and the Basys-3 top of one
// coefficient set, the utilisation report and its checks).
#pragma once

#include <CLI/CLI.hpp>
#include <iosfwd>
#include <string>

namespace flange::cli {

struct SynthOptions {
  std::string coeffs = "coeffs/measurement_sos";  // folder with iir_coeffs_pkg.sv, coeffs.mem
  std::string out = "docs/synthesis.md";
  std::string yosys = "yosys";
  // The core may use at most this share of the LUTs: 1.5 % since contract v2 (split coefficients
  // and error feedback took measurement_sos from 140 to 214 LUT6 sites, 0.67 to 1.03 %).
  double max_core_lut_percent = 1.5;
};

CLI::App* add_synth_command(CLI::App& app, SynthOptions& options);

// Returns 0, 1 (Yosys failed or a check failed; the report is written all the same) or 2.
int run_synth_command(const SynthOptions& options, std::ostream& out, std::ostream& err);

}  // namespace flange::cli
