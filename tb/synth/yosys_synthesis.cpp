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

// used / capacity as "12.34 %".
std::string percent(double used, int capacity) {
  return fmt::format("{:.2f} %", 100.0 * used / capacity);
}

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
  const fs::path log_path = work / (top + "_yosys.log");
  const fs::path script = work / (top + ".ys");
  {
    std::ofstream ys(script);
    ys << "read_verilog -sv " << (set / "iir_coeffs_pkg.sv").string() << "\n"
       << "read_verilog -sv -defer " << sources << "\n"
       << "chparam -set RomFile \"" << (set / "coeffs.mem").string() << "\" " << top << "\n"
       << "synth_xilinx -family xc7 -top " << top << " -flatten\n"
       << "tee -o " << stat_path.string()
       << " stat -tech xilinx\n"
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
  // On failure the work folder stays: the message names its log.
  result.core = run_yosys(request, "iir_core", work);
  result.top = run_yosys(request, "basys3_top", work);
  fs::remove_all(work);
  return result;
}

namespace {

void write_utilisation_table(std::ostream& md, const Utilisation& c, const Utilisation& t,
                             const DeviceCapacity& device) {
  md << "| resource | `iir_core` | share | `basys3_top` | share |\n|---|---|---|---|---|\n";
  md << fmt::format("| LUT6 sites (logic + distributed RAM) | {} | {} | {} | {} |\n", c.lut_sites(),
                    percent(c.lut_sites(), device.luts), t.lut_sites(),
                    percent(t.lut_sites(), device.luts))
     << fmt::format("| of which logic (Yosys estimated LCs) | {} | | {} | |\n", c.estimated_lcs,
                    t.estimated_lcs)
     << fmt::format("| of which distributed RAM (load registers) | {} | | {} | |\n", c.lutram_luts,
                    t.lutram_luts)
     << fmt::format("| LUT cells (LUT1-LUT6) | {} | {} | {} | {} |\n", c.luts,
                    percent(c.luts, device.luts), t.luts, percent(t.luts, device.luts))
     << fmt::format("| INV cells | {} | | {} | |\n", c.inverters, t.inverters)
     << fmt::format("| FF (FDRE/FDSE/FDCE/FDPE) | {} | {} | {} | {} |\n", c.ffs,
                    percent(c.ffs, device.ffs), t.ffs, percent(t.ffs, device.ffs))
     << fmt::format("| CARRY4 | {} | | {} | |\n", c.carry4, t.carry4)
     << fmt::format("| DSP48E1 | {} | {} | {} | {} |\n", c.dsp48e1, percent(c.dsp48e1, device.dsps),
                    t.dsp48e1, percent(t.dsp48e1, device.dsps))
     << fmt::format("| BRAM36 | {} | {} | {} | {} |\n", c.bram36, percent(c.bram36, device.bram36),
                    t.bram36, percent(t.bram36, device.bram36))
     << fmt::format("| IO (IBUF/OBUF) | {} | {} | {} | {} |\n", c.ios, percent(c.ios, device.ios),
                    t.ios, percent(t.ios, device.ios))
     << fmt::format("| logic depth (`ltp`, cells) | {} | | {} | |\n\n", c.logic_depth,
                    t.logic_depth);
}

void write_all_cells_table(std::ostream& md, const Utilisation& c, const Utilisation& t) {
  md << "All cells (`stat -tech xilinx`):\n\n| cell | `iir_core` | `basys3_top` |\n|---|---|---|\n";
  std::map<std::string, std::pair<int, int>> all;
  for (const auto& [cell, n] : c.cells) all[cell].first = n;
  for (const auto& [cell, n] : t.cells) all[cell].second = n;
  for (const auto& [cell, n] : all)
    md << "| " << cell << " | " << n.first << " | " << n.second << " |\n";
}

}  // namespace

std::string synthesis_report_markdown(const SynthesisResult& result, double max_core_lut_percent,
                                      const std::string& failures, const DeviceCapacity& device) {
  const std::string& set_name = result.set_name;
  std::ostringstream md;
  md << "<!-- generated by: "
     << runtime::generated_by("flange synth --coeffs coeffs/" + set_name +
                              " --out docs/synthesis.md")
     << "; Yosys synth_xilinx -family xc7; do not edit -->\n"
     << "# Synthesis (Yosys, XC7A35T)\n\n"
     << "Coefficient set: `" << set_name << "`. Yosys `synth_xilinx -family xc7 -flatten`, then "
     << "`stat -tech xilinx`; percentages of the XC7A35T-1CPG236C (" << device.luts << " LUTs, "
     << device.ffs << " flip-flops, " << device.dsps << " DSP48E1, " << device.bram36 << " BRAM36, "
     << device.ios << " user I/O). Regenerate with `build/flange synth --coeffs "
     << "coeffs/" << set_name << " --out docs/synthesis.md`.\n\n";
  write_utilisation_table(md, result.core.utilisation, result.top.utilisation, device);
  md << "LUTs: the XC7A35T's 20,800 LUTs are LUT6 sites, each of which can hold two smaller LUTs "
        "with shared inputs; the share is occupied sites over 20,800: Yosys's `Estimated number of "
        "LCs` for logic plus the sites of the distributed-RAM cells (RAM32M: 4), which Yosys does "
        "not count as LCs. The raw LUT cell count is the upper bound, shown beside it. INV cells "
        "are counted "
        "apart: Vivado folds them into the logic they drive.\n\n"
        "The core's IO row counts its ports as if it were a top level (it is not one on the "
        "board). Logic depth: `ltp -noff` after deleting every flip-flop, DSP48E1 and block RAM "
        "cell, i.e. the longest chain of LUT, CARRY4, MUXF7/F8 and I/O buffer cells between "
        "registers or pins. It is an estimate only: Yosys has no timing model and there is no "
        "place and route here (use the Vivado script, docs/board.md, for real timing).\n\n"
        "A core shared by several channels (`NumChannels` > 1) grows by its load registers and "
        "their read multiplexer; the core for 1, 4 and 12 channels and for a set per channel is "
        "tabulated in [core.md](core.md#channels) (`bash bench/synth_channels.sh`).\n\n";
  write_all_cells_table(md, result.core.utilisation, result.top.utilisation);
  md << "\nChecks (the `FlangeSynth.*` CTest test): each multiply-accumulate maps to exactly one "
     << "DSP48E1 (core and top: 1); the core occupies at most " << max_core_lut_percent
     << " % of the LUT6 sites: " << (failures.empty() ? "**pass**" : "**FAIL**") << ".\n";
  return md.str();
}

std::string synthesis_summary_line(const SynthesisResult& result, const DeviceCapacity& device) {
  const Utilisation& c = result.core.utilisation;
  const Utilisation& t = result.top.utilisation;
  return fmt::format(
      "{}: core LUT {} ({}), FF {}, DSP48E1 {}; top LUT {} ({}), FF {}, DSP48E1 {}, IO {}; "
      "depth {}/{} cells; {:.1f} s",
      result.set_name, c.luts, percent(c.luts, device.luts), c.ffs, c.dsp48e1, t.luts,
      percent(t.luts, device.luts), t.ffs, t.dsp48e1, t.ios, c.logic_depth, t.logic_depth,
      result.core.seconds + result.top.seconds);
}

}  // namespace flange::tb
