// SPDX-License-Identifier: MIT
// `flange synth`: Yosys `synth_xilinx -family xc7` on the IIR core and on the Basys-3 top for one
// coefficient set, a utilisation report against the XC7A35T and a logic-depth estimate (`ltp`),
// written as Markdown (docs/synthesis.md), with the DSP48E1 and LUT checks of issue 4.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <iosfwd>
#include <map>
#include <string>

namespace flange::host {

// The XC7A35T-1CPG236C (Basys-3).
struct DeviceCapacity {
  int luts = 20800;
  int ffs = 41600;
  int dsps = 90;
  int bram36 = 50;
  int ios = 106;
};

// The cells of one `stat -tech xilinx` run, grouped as the report counts them.
struct Utilisation {
  std::map<std::string, int> cells;  // cell type -> count, as Yosys printed them
  int luts = 0;                      // LUT1..LUT6 cells
  int inverters = 0;                 // INV cells (Vivado folds them into the LUTs they feed)
  int ffs = 0;                       // FDRE, FDSE, FDCE, FDPE
  int carry4 = 0;
  int dsp48e1 = 0;
  double bram36 = 0;      // RAMB36E1 + RAMB18E1 / 2
  int ios = 0;            // IBUF, OBUF, IOBUF, OBUFT
  int estimated_lcs = 0;  // Yosys's estimate of occupied LUT6 sites (two small LUTs share one)
  int lutram_luts = 0;    // LUT6 sites used as distributed RAM (RAM32M: 4, RAM64X1D: 2, ...)
  int lut_sites() const { return estimated_lcs + lutram_luts; }  // logic plus memory
  int logic_depth = 0;  // `ltp` on the netlist without flip-flops, DSPs and BRAMs: cells
};

// Parses the text of `stat -tech xilinx` (cells) and of `ltp` ("length=N").
Utilisation parse_utilisation(const std::string& stat_text, const std::string& ltp_text);

struct SynthOptions {
  std::string coeffs = "coeffs/measurement_sos";  // folder with iir_coeffs_pkg.sv, coeffs.mem
  std::string source_dir;                         // repository root (default: compiled-in)
  std::string out = "docs/synthesis.md";
  std::string yosys = "yosys";
  double max_core_lut_percent = 1.0;  // the core may use at most this share of the LUTs
};

CLI::App* add_synth_command(CLI::App& app, SynthOptions& options);

// The checks of a synthesis result: "" when they pass, otherwise one line per failure. The LUT
// share is occupied LUT6 sites (lut_sites(): logic and distributed RAM) over the device's 20,800
// LUT6 sites.
std::string check_utilisation(const Utilisation& core, const Utilisation& top,
                              double max_core_lut_percent, const DeviceCapacity& device = {});

// Returns 0, 1 (Yosys failed or a check failed; the report is written all the same) or 2.
int run_synth_command(const SynthOptions& options, std::ostream& out, std::ostream& err);

}  // namespace flange::host
