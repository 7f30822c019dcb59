// SPDX-License-Identifier: MIT
// Yosys `synth_xilinx -family xc7 -abc9` of the IIR core and of the Basys-3 top for one
// coefficient set: utilisation against the XC7A35T, a logic-depth estimate (`ltp`), the pre-route
// timing estimate (timing_estimate.h), the one-DSP48E1, LUT-share and slack checks, and the
// Markdown and JSON reports (docs/synthesis.md). `flange synth` is its command line.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "timing_estimate.h"
#include "vivado_report.h"

namespace flange::tb {

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

// The checks of a synthesis result: "" when they pass, otherwise one line per failure. The LUT
// share is occupied LUT6 sites (lut_sites(): logic and distributed RAM) over the device's 20,800
// LUT6 sites.
std::string check_utilisation(const Utilisation& core, const Utilisation& top,
                              double max_core_lut_percent, const DeviceCapacity& device = {});

// Yosys's own `sta` figure: "Latest arrival time in 'top' is N:" -> N ps (cells only, from the
// pins at 0 ps, the clock through its buffers, any endpoint); nullopt when it found no path.
std::optional<int> parse_sta_latest_arrival(const std::string& sta_text);

// Yosys failed; the message names the top, the log and the command that reproduces it.
class SynthesisFailed : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct SynthesisRequest {
  std::filesystem::path data_dir;   // holds rtl/ (runtime/data_dir.h)
  std::filesystem::path coeff_set;  // folder with iir_coeffs_pkg.sv and coeffs.mem
  std::string yosys = "yosys";      // the executable
  int period_ps = 10000;            // the board's 100 MHz clock
  NetAllowance allowance;
};

struct YosysRun {
  std::string top;  // "iir_core" or "basys3_top"
  Utilisation utilisation;
  TimingEstimate timing;
  std::optional<int> yosys_sta_ps;  // parse_sta_latest_arrival of the same netlist
  std::string script_path;
  double seconds = 0;
};

struct SynthesisResult {
  std::string set_name;  // the coefficient set folder's name
  YosysRun core;
  YosysRun top;
};

// The coefficient set folder named `coeffs` (relative: from the working folder, then from
// data_dir). Throws std::invalid_argument naming the first missing source.
std::filesystem::path find_coeff_set(const std::filesystem::path& data_dir,
                                     const std::string& coeffs);

// Runs Yosys on the core and on the board top (tens of seconds). Throws SynthesisFailed.
SynthesisResult synthesise(const SynthesisRequest& request);

// The timing check: "" when every clock of every top keeps at least `min_slack_percent` of the
// period as estimated slack, otherwise one line per top that does not.
std::string check_timing(const SynthesisResult& result, double min_slack_percent);

// What the reports say besides the results: the checks' limits, their verdict, the command.
struct ReportSettings {
  std::string command;  // the flange synth command line that makes the report
  double max_core_lut_percent = 0;
  double min_slack_percent = 0;
  std::string failures;  // "" when every check passed
  NetAllowance allowance;
  std::optional<VivadoReport> vivado;  // routed figures of the board top (--vivado-report)
};

// The Markdown report: per set utilisation, shares of the device, every cell; the timing
// estimate of every top with its five worst paths, Vivado's figures beside it when given; and
// the checks' verdict.
std::string synthesis_report_markdown(const std::vector<SynthesisResult>& results,
                                      const ReportSettings& settings,
                                      const DeviceCapacity& device = {});

// The same figures as JSON (docs/synthesis.md, "JSON").
std::string synthesis_report_json(const std::vector<SynthesisResult>& results,
                                  const ReportSettings& settings,
                                  const DeviceCapacity& device = {});

// One line: the set, LUTs, FFs, DSPs, depth and estimated slack of core and top, the time Yosys
// took.
std::string synthesis_summary_line(const SynthesisResult& result,
                                   const DeviceCapacity& device = {});

}  // namespace flange::tb
