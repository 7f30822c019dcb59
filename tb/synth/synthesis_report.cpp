// SPDX-License-Identifier: MIT
// The reports of `flange synth`: Markdown (docs/synthesis.md) and JSON, from the results of
// yosys_synthesis.cpp, the timing estimate and, when given, Vivado's routed reports.
#include <fmt/format.h>

#include <map>
#include <nlohmann/json.hpp>
#include <ostream>
#include <sstream>

#include "version.h"
#include "yosys_synthesis.h"

namespace flange::tb {

namespace {

// used / capacity as "12.34 %".
std::string percent(double used, int capacity) {
  return fmt::format("{:.2f} %", 100.0 * used / capacity);
}

std::string ns(int ps) { return fmt::format("{:.2f}", ps / 1000.0); }

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
  md << "\n";
}

void write_utilisation(std::ostream& md, const SynthesisResult& r, const DeviceCapacity& device) {
  md << "### `" << r.set_name << "`\n\n";
  write_utilisation_table(md, r.core.utilisation, r.top.utilisation, device);
  write_all_cells_table(md, r.core.utilisation, r.top.utilisation);
}

// One row per top and clock: worst path cells only, with the allowance, slack.
void write_timing_table(std::ostream& md, const std::vector<SynthesisResult>& results) {
  md << "| set | top | clock | endpoints | cells only (ns) | with nets (ns) | slack (ns) | slack "
        "(% of period) | Yosys `sta` (ns) |\n|---|---|---|---|---|---|---|---|---|\n";
  for (const SynthesisResult& r : results) {
    for (const YosysRun* run : {&r.core, &r.top}) {
      const std::string sta = run->yosys_sta_ps ? ns(*run->yosys_sta_ps) : "none";
      for (const ClockEstimate& c : run->timing.clocks) {
        md << fmt::format("| `{}` | `{}` | `{}` | {} | {} | {} | {} | {:.1f} % | {} |\n",
                          r.set_name, run->top, c.clock, c.endpoints, ns(c.worst_cells_ps),
                          ns(c.worst_ps), ns(c.slack_ps), 100.0 * c.slack_ps / c.period_ps, sta);
      }
    }
  }
  md << "\n";
}

void write_path(std::ostream& md, int rank, const TimingPath& p) {
  md << fmt::format(
      "{}. `{}` -> `{}` ({}): {} ns = {} cells + {} nets, slack {} ns, {} logic "
      "levels<br>",
      rank, p.from, p.to, p.to_pin, ns(p.total_ps()), ns(p.cells_ps), ns(p.nets_ps), ns(p.slack_ps),
      p.logic_levels);
  for (std::size_t i = 0; i < p.steps.size(); ++i) {
    const PathStep& s = p.steps[i];
    md << fmt::format("{}{} {} {} `{}` (fo {}) +{}", i == 0 ? "" : " &rarr; ", s.type, s.arc,
                      ns(s.cell_ps), s.net, s.fanout, ns(s.net_ps));
  }
  md << fmt::format(" &rarr; setup {}\n", ns(p.setup_ps));
}

void write_worst_paths(std::ostream& md, const std::vector<SynthesisResult>& results) {
  for (const SynthesisResult& r : results) {
    for (const YosysRun* run : {&r.core, &r.top}) {
      md << "`" << run->top << "`, `" << r.set_name << "`:\n\n";
      int rank = 1;
      for (const TimingPath& p : run->timing.worst_paths) write_path(md, rank++, p);
      md << "\n";
    }
  }
}

void write_vivado(std::ostream& md, const std::vector<SynthesisResult>& results,
                  const VivadoReport& v) {
  md << "### Routed (Vivado)\n\nFrom `" << v.dir.string()
     << "` (`report_timing_summary`, `report_utilization` of `rtl/board/vivado_build.tcl`), "
        "beside the estimate of the board top of `"
     << results.front().set_name << "`:\n\n| figure | estimate (Yosys) | routed (Vivado) |\n"
     << "|---|---|---|\n";
  const YosysRun& top = results.front().top;
  const int est_slack = top.timing.clocks.empty() ? 0 : top.timing.worst_slack_ps();
  md << fmt::format("| worst setup slack (ns) | {} | {:.3f} |\n", ns(est_slack), v.timing.wns_ns);
  for (const VivadoClock& c : v.timing.clocks) {
    md << fmt::format("| clock `{}` (period {:.3f} ns): WNS / WHS (ns) | | {} / {} |\n", c.name,
                      c.period_ns, c.wns_ns ? fmt::format("{:.3f}", *c.wns_ns) : "NA",
                      c.whs_ns ? fmt::format("{:.3f}", *c.whs_ns) : "NA");
  }
  md << fmt::format("| failing / timed endpoints | | {} / {} |\n", v.timing.failing_endpoints,
                    v.timing.total_endpoints);
  if (v.timing.worst_path) {
    const VivadoPath& p = *v.timing.worst_path;
    const TimingPath* e = top.timing.worst_paths.empty() ? nullptr : &top.timing.worst_paths[0];
    md << fmt::format("| worst path: cells / nets (ns) | {} / {} | {:.3f} / {:.3f} |\n",
                      e ? ns(e->cells_ps) : "-", e ? ns(e->nets_ps) : "-", p.logic_ns, p.route_ns)
       << fmt::format("| worst path: from -> to | `{}` -> `{}` | `{}` -> `{}` |\n",
                      e ? e->from : "-", e ? e->to : "-", p.source, p.destination)
       << fmt::format("| worst path: logic levels | {} | {} |\n", e ? e->logic_levels : 0,
                      p.logic_levels);
  }
  const Utilisation& u = top.utilisation;
  const VivadoUtilisation& vu = v.utilisation;
  md << fmt::format("| Slice LUTs (LUT6 sites) | {} | {} |\n", u.lut_sites(), vu.slice_luts)
     << fmt::format("| Slice registers | {} | {} |\n", u.ffs, vu.slice_registers);
  if (vu.dsps) md << fmt::format("| DSPs | {} | {} |\n", u.dsp48e1, *vu.dsps);
  md << "\n";
}

void write_timing_method(std::ostream& md, const ReportSettings& s) {
  md << "## Timing estimate\n\n**An estimate before place and route, not a timing sign-off.** "
        "Every register-to-register path (flip-flops, the DSP48E1's registers, the distributed "
        "RAM's write port) of the Yosys netlist, per clock: the sum of the cells' delays from "
        "Yosys's xc7 cell models (the specify blocks of `cells_sim.v`, from the prjxray timing "
        "database of the Artix-7, as `read_verilog -lib -specify` and `sta` elaborate them; clock "
        "to output, each arc's worst of rise and fall, the setup time) plus a net-delay "
        "allowance of "
     << ns(s.allowance.base_ps) << " ns + " << ns(s.allowance.per_fanout_ps)
     << " ns per load for every net (FloPoCo's net model for the xc7z020-1, whose programmable "
        "logic is Artix-7 fabric at the same -1 speed grade: `typicalLocalRoutingDelay_` 0.5 ns, "
        "`fanoutConstant_` 2 ns per 200 loads), except nets inside a slice or cascade (CARRY4 to "
        "CARRY4, LUT to MUXF7, MUXF7 to MUXF8, a LUT that drives only a CARRY4), which cost "
        "none. The clock is ideal (no skew, jitter or uncertainty); paths from or to the pins are "
        "not timed. Yosys's own `sta` figure is shown beside it: cells only, from the pins as "
        "well, with the clock's buffers.\n\nWhere it errs: FloPoCo's own nine routed nets of "
        "that part (fanout 1 to 102) took 0.13 to 1.71 ns more than this allowance; the cell "
        "models err the other way (a LUT input costs 0.127 to 0.642 ns by pin where Vivado's "
        "-1 figure, quoted by FloPoCo, is 0.124 ns after it has swapped the critical signal to "
        "the fastest pin). Vivado's routed report (`--vivado-report`) is the figure to sign off "
        "on. The check: every clock of every top keeps at least "
     << s.min_slack_percent << " % of the period as estimated slack.\n\n";
}

}  // namespace

std::string synthesis_report_markdown(const std::vector<SynthesisResult>& results,
                                      const ReportSettings& s, const DeviceCapacity& device) {
  std::ostringstream md;
  md << "<!-- generated by: " << runtime::generated_by(s.command)
     << "; Yosys synth_xilinx -family xc7 -abc9; do not edit -->\n"
     << "# Synthesis (Yosys, XC7A35T)\n\n"
     << "Yosys `synth_xilinx -family xc7 -flatten -abc9`, then `stat -tech xilinx`, for the core "
        "and the Basys-3 top of each coefficient set; percentages of the XC7A35T-1CPG236C ("
     << device.luts << " LUTs, " << device.ffs << " flip-flops, " << device.dsps << " DSP48E1, "
     << device.bram36 << " BRAM36, " << device.ios << " user I/O); then a timing estimate at the "
     << "board's 100 MHz. Regenerate with `build/" << s.command << "` (beside it: the same figures "
     << "as JSON).\n\n";
  write_timing_method(md, s);
  write_timing_table(md, results);
  md << "The five worst paths of each top, one per register: from the launching register to the "
        "capturing one, by their RTL names; then each cell (type, arc, delay in ns) and the net "
        "it drives (its RTL name; `~name`: a net Yosys made from that RTL signal; `@file:line`: "
        "the RTL line of the cell; its fanout and allowance in ns).\n\n";
  write_worst_paths(md, results);
  if (s.vivado) write_vivado(md, results, *s.vivado);
  md << "## Utilisation\n\n"
        "LUTs: the XC7A35T's 20,800 LUTs are LUT6 sites, each of which can hold two smaller LUTs "
        "with shared inputs; the share is occupied sites over 20,800: Yosys's `Estimated number of "
        "LCs` for logic plus the sites of the distributed-RAM cells (RAM32M: 4), which Yosys does "
        "not count as LCs. The raw LUT cell count is the upper bound, shown beside it. INV cells "
        "are counted apart: Vivado folds them into the logic they drive.\n\n"
        "The core's IO row counts its ports as if it were a top level (it is not one on the "
        "board). Logic depth: `ltp -noff` after deleting every flip-flop, DSP48E1 and block RAM "
        "cell, i.e. the longest chain of LUT, CARRY4, MUXF7/F8 and I/O buffer cells between "
        "registers or pins.\n\n"
        "A core shared by several channels (`NumChannels` > 1) grows by its load registers and "
        "their read multiplexer; the core for 1, 4 and 12 channels and for a set per channel is "
        "tabulated in [core.md](core.md#channels) (`bash bench/synth_channels.sh`).\n\n";
  for (const SynthesisResult& r : results) write_utilisation(md, r, device);
  md << "## Checks\n\nThe checks of this run (the `FlangeSynth.*` CTest tests run them per set "
        "with "
     << "their own limits, tests/cli/CMakeLists.txt): each multiply-accumulate maps to exactly one "
     << "DSP48E1 (core and top: 1); the core occupies at most " << s.max_core_lut_percent
     << " % of the LUT6 sites; every top keeps at least " << s.min_slack_percent
     << " % of the period as estimated slack: " << (s.failures.empty() ? "**pass**" : "**FAIL**")
     << ".\n";
  if (!s.failures.empty()) md << "\n```\n" << s.failures << "```\n";
  md << "\n## JSON\n\nBeside this report (`--json PATH` to put it elsewhere): `generated_by`; "
        "`net_allowance` (`base_ns`, `per_fanout_ns`, `source`); `checks` (the limits, `pass`, "
        "`failures`); `sets`, each with `set` and `tops`: per top (`iir_core`, `basys3_top`) "
        "`utilisation` (the table's rows and every cell) and `timing`: `clocks` (`clock`, "
        "`period_ns`, `endpoints`, `cells_only_ns`, `worst_ns`, `slack_ns`, `slack_percent`), "
        "`worst_paths` (`from`, `to`, `to_pin`, `total_ns` = `cells_ns` + `nets_ns`, `setup_ns`, "
        "`slack_ns`, `logic_levels`, `steps`: `cell`, `type`, `arc`, `cell_ns`, `net`, `fanout`, "
        "`net_ns`), `yosys_sta_latest_arrival_ns`, `types_without_model`; `vivado`: null, or "
        "with `--vivado-report` `wns_ns`, `tns_ns`, `failing_endpoints`, `total_endpoints`, "
        "`whs_ns`, `clocks`, `worst_path` and `utilisation`.\n";
  return md.str();
}

std::string synthesis_summary_line(const SynthesisResult& result, const DeviceCapacity& device) {
  const Utilisation& c = result.core.utilisation;
  const Utilisation& t = result.top.utilisation;
  auto slack = [](const YosysRun& run) {
    return run.timing.clocks.empty() ? std::string("none") : ns(run.timing.worst_slack_ps());
  };
  return fmt::format(
      "{}: core LUT {} ({}), FF {}, DSP48E1 {}; top LUT {} ({}), FF {}, DSP48E1 {}, IO {}; "
      "depth {}/{} cells; estimated slack {}/{} ns at 100 MHz; {:.1f} s",
      result.set_name, c.luts, percent(c.luts, device.luts), c.ffs, c.dsp48e1, t.luts,
      percent(t.luts, device.luts), t.ffs, t.dsp48e1, t.ios, c.logic_depth, t.logic_depth,
      slack(result.core), slack(result.top), result.core.seconds + result.top.seconds);
}

namespace {

using nlohmann::json;

json utilisation_json(const Utilisation& u) {
  return {{"lut_sites", u.lut_sites()},   {"estimated_lcs", u.estimated_lcs},
          {"lutram_luts", u.lutram_luts}, {"luts", u.luts},
          {"inverters", u.inverters},     {"ffs", u.ffs},
          {"carry4", u.carry4},           {"dsp48e1", u.dsp48e1},
          {"bram36", u.bram36},           {"ios", u.ios},
          {"logic_depth", u.logic_depth}, {"cells", u.cells}};
}

json path_json(const TimingPath& p) {
  json steps = json::array();
  for (const PathStep& s : p.steps) {
    steps.push_back({{"cell", s.cell},
                     {"type", s.type},
                     {"arc", s.arc},
                     {"cell_ns", s.cell_ps / 1e3},
                     {"net", s.net},
                     {"fanout", s.fanout},
                     {"net_ns", s.net_ps / 1e3}});
  }
  return {{"clock", p.clock},
          {"from", p.from},
          {"to", p.to},
          {"to_pin", p.to_pin},
          {"total_ns", p.total_ps() / 1e3},
          {"cells_ns", p.cells_ps / 1e3},
          {"nets_ns", p.nets_ps / 1e3},
          {"setup_ns", p.setup_ps / 1e3},
          {"slack_ns", p.slack_ps / 1e3},
          {"logic_levels", p.logic_levels},
          {"steps", steps}};
}

json run_json(const YosysRun& run) {
  json clocks = json::array(), paths = json::array();
  for (const ClockEstimate& c : run.timing.clocks) {
    clocks.push_back({{"clock", c.clock},
                      {"period_ns", c.period_ps / 1e3},
                      {"endpoints", c.endpoints},
                      {"cells_only_ns", c.worst_cells_ps / 1e3},
                      {"worst_ns", c.worst_ps / 1e3},
                      {"slack_ns", c.slack_ps / 1e3},
                      {"slack_percent", 100.0 * c.slack_ps / c.period_ps}});
  }
  for (const TimingPath& p : run.timing.worst_paths) paths.push_back(path_json(p));
  return {{"utilisation", utilisation_json(run.utilisation)},
          {"timing",
           {{"clocks", clocks},
            {"worst_paths", paths},
            {"yosys_sta_latest_arrival_ns",
             run.yosys_sta_ps ? json(*run.yosys_sta_ps / 1e3) : json(nullptr)},
            {"types_without_model", run.timing.types_without_model}}}};
}

json vivado_json(const VivadoReport& v) {
  auto opt = [](const auto& x) { return x ? json(*x) : json(nullptr); };
  json clocks = json::array();
  for (const VivadoClock& c : v.timing.clocks) {
    clocks.push_back({{"clock", c.name},
                      {"period_ns", c.period_ns},
                      {"wns_ns", opt(c.wns_ns)},
                      {"whs_ns", opt(c.whs_ns)}});
  }
  json out = {{"dir", v.dir.string()},
              {"wns_ns", v.timing.wns_ns},
              {"tns_ns", v.timing.tns_ns},
              {"failing_endpoints", v.timing.failing_endpoints},
              {"total_endpoints", v.timing.total_endpoints},
              {"whs_ns", opt(v.timing.whs_ns)},
              {"clocks", clocks},
              {"utilisation",
               {{"device", v.utilisation.device},
                {"slice_luts", v.utilisation.slice_luts},
                {"slice_registers", v.utilisation.slice_registers},
                {"dsps", opt(v.utilisation.dsps)},
                {"block_ram_tiles", opt(v.utilisation.block_ram_tiles)}}}};
  if (v.timing.worst_path) {
    const VivadoPath& p = *v.timing.worst_path;
    out["worst_path"] = {{"slack_ns", p.slack_ns},        {"from", p.source},
                         {"to", p.destination},           {"data_path_ns", p.data_path_ns},
                         {"logic_ns", p.logic_ns},        {"route_ns", p.route_ns},
                         {"logic_levels", p.logic_levels}};
  }
  return out;
}

}  // namespace

std::string synthesis_report_json(const std::vector<SynthesisResult>& results,
                                  const ReportSettings& s, const DeviceCapacity& device) {
  json sets = json::array();
  for (const SynthesisResult& r : results) {
    sets.push_back({{"set", r.set_name},
                    {"tops", {{r.core.top, run_json(r.core)}, {r.top.top, run_json(r.top)}}}});
  }
  json out = {{"generated_by", runtime::generated_by(s.command)},
              {"estimate",
               "pre-route: cell delays from Yosys's xc7 models plus a net allowance by "
               "fanout; not a sign-off (docs/synthesis.md)"},
              {"device",
               {{"luts", device.luts},
                {"ffs", device.ffs},
                {"dsps", device.dsps},
                {"bram36", device.bram36},
                {"ios", device.ios}}},
              {"net_allowance",
               {{"base_ns", s.allowance.base_ps / 1e3},
                {"per_fanout_ns", s.allowance.per_fanout_ps / 1e3},
                {"dedicated_connections", s.allowance.dedicated_connections},
                {"source", "FloPoCo src/Targets/Zynq7000.hpp (xc7z020-1)"}}},
              {"checks",
               {{"max_core_lut_percent", s.max_core_lut_percent},
                {"min_slack_percent", s.min_slack_percent},
                {"pass", s.failures.empty()},
                {"failures", s.failures}}},
              {"sets", sets}};
  out["vivado"] = s.vivado ? vivado_json(*s.vivado) : json(nullptr);
  return out.dump(2) + "\n";
}

}  // namespace flange::tb
