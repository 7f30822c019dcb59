// SPDX-License-Identifier: MIT
// Vivado's routed figures for the board top, read from the reports rtl/board/vivado_build.tcl
// writes: `report_timing_summary` (timing_summary.rpt: the Design Timing Summary, Clock Summary
// and Intra Clock tables, and the worst setup path) and `report_utilization` (utilization.rpt: the
// Slice Logic, Memory and DSP tables). `flange synth --vivado-report DIR` sets them beside the
// estimate (timing_estimate.h).
#pragma once

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace flange::tb {

struct VivadoClock {
  std::string name;  // "sys_clk_pin"
  double period_ns = 0;
  std::optional<double> wns_ns;  // from the Intra Clock Table; absent when Vivado printed none
  std::optional<double> whs_ns;
};

// The worst setup path, from the first "Max Delay Paths" entry.
struct VivadoPath {
  double slack_ns = 0;
  std::string source, destination;
  double data_path_ns = 0, logic_ns = 0, route_ns = 0;
  int logic_levels = 0;
};

struct VivadoTiming {
  double wns_ns = 0, tns_ns = 0;
  int failing_endpoints = 0, total_endpoints = 0;
  std::optional<double> whs_ns;
  std::vector<VivadoClock> clocks;
  std::optional<VivadoPath> worst_path;
};

struct VivadoUtilisation {
  std::string device;  // "7a35tcpg236-1", from the header
  int slice_luts = 0, slice_registers = 0;
  std::optional<int> lut_as_memory, f7_muxes, f8_muxes, dsps, bonded_iob;
  std::optional<double> block_ram_tiles;
};

struct VivadoReport {
  std::filesystem::path dir;
  VivadoTiming timing;
  VivadoUtilisation utilisation;
};

// A report file is missing or unreadable.
class VivadoReportMissing : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};
// A report does not hold a table or field in the layout Vivado writes: "FILE:LINE: field ...".
class VivadoReportError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The text of `report_timing_summary`; `file` names it in errors.
VivadoTiming parse_timing_summary(const std::string& text, const std::string& file);
// The text of `report_utilization`.
VivadoUtilisation parse_utilization(const std::string& text, const std::string& file);
// DIR/timing_summary.rpt and DIR/utilization.rpt (the names vivado_build.tcl writes).
VivadoReport read_vivado_report(const std::filesystem::path& dir);

}  // namespace flange::tb
