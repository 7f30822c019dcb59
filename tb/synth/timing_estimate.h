// SPDX-License-Identifier: MIT
// A pre-route timing estimate of a Yosys netlist for the Artix-7: every register-to-register path
// as the sum of its cells' delays (Yosys's xc7 cell models, cell_timing.h) plus a net-delay
// allowance by fanout, against a clock period. An estimate only: there is no placement, so no
// routed net delay and no clock skew; Vivado's routed report (vivado_report.h) is the real figure.
#pragma once

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "cell_timing.h"

namespace flange::tb {

// The allowance for one routed net, by its fanout (the cell input pins it drives): FloPoCo's net
// model for the xc7z020-1 (Zynq-7000 programmable logic is Artix-7 fabric at the same -1 speed
// grade; FloPoCo src/Targets/Zynq7000.hpp: typicalLocalRoutingDelay_ = 0.5 ns, fanoutConstant_ =
// 2 ns / 200), i.e. 0.5 ns + 0.01 ns per load. FloPoCo's own routed data points for that part
// (Zynq7000.cpp, fanoutDelay()) lie 0.13 to 1.71 ns above it per net; the cell models err the
// other way (a LUT's slowest input is 0.642 ns in cells_sim.v, 0.124 ns in Vivado's -1 report
// that FloPoCo quotes): docs/synthesis.md compares the two.
struct NetAllowance {
  int base_ps = 500;
  int per_fanout_ps = 10;
  // Nets inside a slice or a cascade cost no routing: CARRY4 CO[3] -> CARRY4 CI, a LUT ->
  // MUXF7, MUXF7 -> MUXF8, and a LUT that drives only a CARRY4's S or DI pin (UG474: each sits
  // beside the carry chain or the wide multiplexer it feeds).
  bool dedicated_connections = true;
  int ps(int fanout) const { return base_ps + per_fanout_ps * fanout; }
};

// One stage of a path: a cell arc, then the net its output drives.
struct PathStep {
  std::string cell;  // the Yosys cell name
  std::string type;  // "LUT6"
  std::string arc;   // "I3->O", or "C->Q" for the launching register
  int cell_ps = 0;
  std::string net;  // the RTL name of the net driven (or the nearest named source)
  int fanout = 0;
  int net_ps = 0;  // the allowance charged for it on the way to the next pin
};

struct TimingPath {
  std::string clock;   // the capture clock's top-level port ("clk_i")
  std::string from;    // RTL name of the launching register's output ("u_mac.p_q[47]")
  std::string to;      // RTL name of the capturing register ("acc_q[3]") and its pin
  std::string to_pin;  // "FDRE D"
  std::vector<PathStep> steps;
  int setup_ps = 0;
  int cells_ps = 0;  // clock-to-out, arcs and setup
  int nets_ps = 0;   // the allowance
  int total_ps() const { return cells_ps + nets_ps; }
  int slack_ps = 0;      // period - total
  int logic_levels = 0;  // combinational cells on the path
};

struct ClockEstimate {
  std::string clock;
  int period_ps = 0;
  int worst_ps = 0;        // the worst path (cells + nets)
  int worst_cells_ps = 0;  // the worst path counting cells only (no allowance)
  int slack_ps = 0;        // period - worst_ps
  int endpoints = 0;       // register inputs timed
};

struct TimingEstimate {
  std::vector<ClockEstimate> clocks;             // one per clock
  std::vector<TimingPath> worst_paths;           // the worst, one per endpoint, worst first
  std::vector<std::string> types_without_model;  // cell types that break paths (none expected)
  int worst_slack_ps() const;                    // over all clocks
};

// The netlist or the cell models cannot be timed (a combinational loop, a cell with no model).
class TimingEstimateError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Times the module `top` of a Yosys JSON netlist (write_json after synth_xilinx -flatten) at
// `period_ps` and keeps the `max_paths` worst paths. Throws TimingEstimateError.
TimingEstimate estimate_timing(const std::string& netlist_json, const std::string& top,
                               const CellTimingLibrary& library, int period_ps,
                               const NetAllowance& allowance = {}, int max_paths = 5);

}  // namespace flange::tb
