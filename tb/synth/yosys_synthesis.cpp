// SPDX-License-Identifier: MIT
#include "yosys_synthesis.h"

#include <fmt/format.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "version.h"

namespace flange::tb {
namespace fs = std::filesystem;

namespace {

// The board sources, in dependency order (rtl/board/, docs/board.md).
const char* const kBoardSources[] = {
    "crc8.sv",          "uart_rx.sv",         "uart_tx.sv",
    "frame_decoder.sv", "frame_encoder.sv",   "clearance_display.sv",
    "seven_seg.sv",     "button_debounce.sv", "basys3_top.sv"};

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path.string());
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// One Yosys run: read, synth_xilinx, stat, then ltp on a copy without sequential cells.
YosysRun run_yosys(const SynthesisRequest& request, const std::string& top, const fs::path& work) {
  const fs::path& root = request.data_dir;
  const fs::path& set = request.coeff_set;
  const fs::path rtl = root / "rtl";
  std::string sources = (rtl / "iir_mac.sv").string() + " " + (rtl / "iir_core.sv").string();
  if (top != "iir_core") {
    for (const char* file : kBoardSources) sources += " " + (rtl / "board" / file).string();
  }
  const fs::path stat_path = work / (top + "_stat.txt");
  const fs::path ltp_path = work / (top + "_ltp.txt");
  const fs::path sta_path = work / (top + "_sta.txt");
  const fs::path netlist_path = work / (top + "_netlist.json");
  const fs::path models_path = work / (top + "_cells.il");
  const fs::path log_path = work / (top + "_yosys.log");
  const fs::path script = work / (top + ".ys");
  {
    std::ofstream ys(script);
    ys << "read_verilog -sv " << (set / "iir_coeffs_pkg.sv").string() << "\n"
       << "read_verilog -sv -defer " << sources << "\n"
       << "chparam -set RomFile \"" << (set / "coeffs.mem").string() << "\" " << top
       << "\n"
       // -abc9: timing-driven LUT mapping with the same cell delays the estimate uses.
       << "synth_xilinx -family xc7 -top " << top << " -flatten -abc9\n"
       << "tee -o " << stat_path.string() << " stat -tech xilinx\n"
       << "write_json " << netlist_path.string()
       << "\n"
       // The cell models with their specify blocks; `sta` elaborates them for each parameter set
       // in use, and write_rtlil hands those to the estimate (cell_timing.h).
       << "read_verilog -lib -specify +/xilinx/cells_sim.v\n"
       << "tee -o " << sta_path.string() << " sta\n"
       << "select =" << top << "/t:* %M =$paramod*\n"
       << "write_rtlil -selected " << models_path.string() << "\n"
       << "select -clear\n"
       // Logic depth: cut the netlist at every register (flip-flops, the DSP48E1 with its
       // internal registers, block RAM); ltp then counts the cells on the longest path.
       << "delete t:FDRE t:FDSE t:FDCE t:FDPE t:DSP48E1 t:RAMB36E1 t:RAMB18E1\n"
       << "tee -o " << ltp_path.string() << " ltp -noff\n";
  }
  const std::string command = fmt::format("{} -q -l {} -s {} > /dev/null 2>&1", request.yosys,
                                          log_path.string(), script.string());
  const auto start = std::chrono::steady_clock::now();
  const int status = std::system(command.c_str());
  YosysRun run;
  run.top = top;
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run.script_path = script.string();
  if (status != 0) {
    throw SynthesisFailed("yosys failed for " + top + "; see " + log_path.string() +
                          " (reproduce: " + request.yosys + " -s " + script.string() + ")");
  }
  run.utilisation = parse_utilisation(read_text(stat_path), read_text(ltp_path));
  run.yosys_sta_ps = parse_sta_latest_arrival(read_text(sta_path));
  try {
    const CellTimingLibrary models = CellTimingLibrary::parse(read_text(models_path));
    run.timing =
        estimate_timing(read_text(netlist_path), top, models, request.period_ps, request.allowance);
  } catch (const std::runtime_error& e) {  // CellTimingError, TimingEstimateError
    throw SynthesisFailed("timing estimate of " + top + ": " + e.what() + " (netlist " +
                          netlist_path.string() + ", cell models " + models_path.string() + ")");
  }
  return run;
}

}  // namespace

Utilisation parse_utilisation(const std::string& stat_text, const std::string& ltp_text) {
  Utilisation u;
  static const std::regex cell_line(R"(^\s+([A-Z][A-Z0-9_]*)\s+(\d+)\s*$)");
  static const std::regex lcs_line(R"(Estimated number of LCs:\s+(\d+))");
  std::istringstream lines(stat_text);
  std::string line;
  std::smatch m;
  while (std::getline(lines, line)) {
    if (std::regex_match(line, m, cell_line)) {
      u.cells[m[1]] += std::stoi(m[2]);
    } else if (std::regex_search(line, m, lcs_line)) {
      u.estimated_lcs = std::stoi(m[1]);
    }
  }
  auto count = [&](const char* cell) {
    auto it = u.cells.find(cell);
    return it == u.cells.end() ? 0 : it->second;
  };
  for (const char* lut : {"LUT1", "LUT2", "LUT3", "LUT4", "LUT5", "LUT6"}) u.luts += count(lut);
  for (const char* ff : {"FDRE", "FDSE", "FDCE", "FDPE"}) u.ffs += count(ff);
  // Distributed RAM primitives and the LUT6 sites each occupies (UG474, SLICEM).
  static const std::map<std::string, int> lutram_sites = {
      {"RAM32X1S", 1},  {"RAM64X1S", 1},  {"RAM32X1D", 2},  {"RAM64X1D", 2},
      {"RAM128X1S", 2}, {"RAM128X1D", 4}, {"RAM256X1S", 4}, {"RAM32M", 4},
      {"RAM64M", 4},    {"RAM32M16", 8},  {"RAM64M8", 8}};
  for (const auto& [cell, sites] : lutram_sites) u.lutram_luts += sites * count(cell.c_str());
  u.inverters = count("INV");
  u.carry4 = count("CARRY4");
  u.dsp48e1 = count("DSP48E1");
  u.bram36 = count("RAMB36E1") + count("RAMB18E1") / 2.0;
  for (const char* io : {"IBUF", "OBUF", "IOBUF", "OBUFT"}) u.ios += count(io);
  static const std::regex ltp_line(R"(length=(\d+))");
  if (std::regex_search(ltp_text, m, ltp_line)) u.logic_depth = std::stoi(m[1]);
  return u;
}

std::string check_utilisation(const Utilisation& core, const Utilisation& top,
                              double max_core_lut_percent, const DeviceCapacity& device) {
  std::string failures;
  if (core.dsp48e1 != 1) {
    failures += fmt::format(
        "the core's multiply-accumulate maps to {} DSP48E1, expected exactly 1\n", core.dsp48e1);
  }
  if (top.dsp48e1 != 1) {
    failures += fmt::format(
        "the board top uses {} DSP48E1, expected exactly 1 (the core's multiply-accumulate)\n",
        top.dsp48e1);
  }
  const double core_percent = 100.0 * core.lut_sites() / device.luts;
  if (core.estimated_lcs <= 0 || core_percent > max_core_lut_percent) {
    failures += fmt::format(
        "the core occupies {} LUT6 sites ({} logic, {} distributed RAM; {} LUT cells), {:.2f} % of "
        "the device, above {:.2f} %\n",
        core.lut_sites(), core.estimated_lcs, core.lutram_luts, core.luts, core_percent,
        max_core_lut_percent);
  }
  return failures;
}

std::optional<int> parse_sta_latest_arrival(const std::string& sta_text) {
  static const std::regex latest(R"(Latest arrival time in '[^']*' is (-?\d+):)");
  std::smatch m;
  if (!std::regex_search(sta_text, m, latest)) return std::nullopt;
  return std::stoi(m[1]);
}

std::string check_timing(const SynthesisResult& result, double min_slack_percent) {
  std::string failures;
  for (const YosysRun* run : {&result.core, &result.top}) {
    if (run->timing.clocks.empty()) {
      failures += fmt::format("{} ({}): no register-to-register path was timed\n", run->top,
                              result.set_name);
    }
    for (const ClockEstimate& c : run->timing.clocks) {
      const double percent = 100.0 * c.slack_ps / c.period_ps;
      if (percent >= min_slack_percent) continue;
      failures += fmt::format(
          "{} ({}), clock {}: estimated slack {:.3f} ns is {:.2f} % of the {:.2f} ns period, "
          "below {:.1f} % (worst path {:.2f} ns)\n",
          run->top, result.set_name, c.clock, c.slack_ps / 1000.0, percent, c.period_ps / 1000.0,
          min_slack_percent, c.worst_ps / 1000.0);
    }
    if (!run->timing.types_without_model.empty()) {
      std::string types;
      for (const std::string& t : run->timing.types_without_model) types += " " + t;
      failures += fmt::format("{} ({}): cells without a timing model break paths:{}\n", run->top,
                              result.set_name, types);
    }
  }
  return failures;
}

fs::path find_coeff_set(const fs::path& data_dir, const std::string& coeffs) {
  // A relative folder is looked up from the working folder, then from the data folder.
  fs::path set = fs::absolute(coeffs);
  if (!fs::exists(set) && fs::path(coeffs).is_relative()) set = data_dir / coeffs;
  for (const fs::path& f :
       {data_dir / "rtl" / "iir_core.sv", set / "iir_coeffs_pkg.sv", set / "coeffs.mem"}) {
    if (!fs::exists(f)) throw std::invalid_argument(f.string() + " is missing");
  }
  return set;
}

SynthesisResult synthesise(const SynthesisRequest& request) {
  const fs::path work =
      fs::temp_directory_path() /
      fmt::format("flange_synth_{}_{}", request.coeff_set.filename().string(), ::getpid());
  fs::create_directories(work);
  SynthesisResult result;
  result.set_name = request.coeff_set.filename().string();
  // On failure the work folder stays: the message names its log and files.
  result.core = run_yosys(request, "iir_core", work);
  result.top = run_yosys(request, "basys3_top", work);
  fs::remove_all(work);
  return result;
}

}  // namespace flange::tb
