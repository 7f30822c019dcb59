// SPDX-License-Identifier: MIT
// `flange synth`: the command line of tb/synth (Yosys on the core and the Basys-3 top of each
// coefficient set given, the utilisation and timing-estimate reports and their checks; Vivado's
// routed reports beside them when given).
#pragma once

#include <CLI/CLI.hpp>
#include <iosfwd>
#include <string>
#include <vector>

namespace flange::cli {

struct SynthOptions {
  // Folders with iir_coeffs_pkg.sv, coeffs.mem; one or more.
  std::vector<std::string> coeffs = {"coeffs/measurement_sos"};
  std::string out = "docs/synthesis.md";
  std::string json;  // "" : beside the Markdown report, with the extension .json
  std::string yosys = "yosys";
  std::string vivado_report;  // a folder with timing_summary.rpt and utilization.rpt, or ""
  // The core may use at most this share of the LUTs: 1.5 % since contract v2 (split coefficients
  // and error feedback took measurement_sos from 140 to 214 LUT6 sites, 0.67 to 1.03 %).
  double max_core_lut_percent = 1.5;
  // Every top keeps at least this share of the 10 ns period as estimated slack: a margin for what
  // the pre-route estimate cannot see (placement, congestion, clock uncertainty;
  // docs/synthesis.md).
  double min_slack_percent = 20;
};

CLI::App* add_synth_command(CLI::App& app, SynthOptions& options);

// Returns 0 or 1 (a check failed; the reports are written all the same when Yosys ran). Throws
// when Yosys failed or a Vivado report or the data folder is missing (1), and when a coefficient
// set is missing or a Vivado report does not parse (2: one line names file, line and field).
int run_synth_command(const SynthOptions& options, std::ostream& out, std::ostream& err);

}  // namespace flange::cli
