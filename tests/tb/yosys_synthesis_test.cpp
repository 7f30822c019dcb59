// SPDX-License-Identifier: MIT
// `flange synth`: the parsing of Yosys's report and the checks, on hand-written and captured
// reports (the Yosys run itself is the FlangeSynth.* CTest test, tests/cli/CMakeLists.txt).
#include "yosys_synthesis.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

namespace flange::tb {
namespace {

const char* const kStat = R"(
15. Printing statistics.

=== basys3_top ===

   Number of wires:                680
   Number of cells:               1386
     BUFG                            1
     CARRY4                         51
     DSP48E1                         1
     FDRE                          513
     FDSE                           11
     IBUF                           19
     INV                            41
     LUT2                          215
     LUT6                          137
     RAMB18E1                        1
     RAM32M                          4
     OBUF                           29

   Estimated number of LCs:        300
)";

TEST(YosysSynthesis, ParsesCellsAndDepth) {
  const Utilisation u =
      parse_utilisation(kStat, "Longest topological path in basys3_top (length=17):\n");
  EXPECT_EQ(u.luts, 215 + 137);
  EXPECT_EQ(u.inverters, 41);
  EXPECT_EQ(u.ffs, 524);
  EXPECT_EQ(u.carry4, 51);
  EXPECT_EQ(u.dsp48e1, 1);
  EXPECT_DOUBLE_EQ(u.bram36, 0.5);
  EXPECT_EQ(u.ios, 48);
  EXPECT_EQ(u.estimated_lcs, 300);
  EXPECT_EQ(u.lutram_luts, 16);
  EXPECT_EQ(u.lut_sites(), 316);
  EXPECT_EQ(u.logic_depth, 17);
  EXPECT_EQ(u.cells.at("BUFG"), 1);
}

TEST(YosysSynthesis, ChecksOneDspAndTheLutShare) {
  Utilisation core;
  core.dsp48e1 = 1;
  core.estimated_lcs = 208;  // exactly 1 % of 20,800
  core.luts = 216;
  Utilisation top = core;
  EXPECT_EQ(check_utilisation(core, top, 1.0), "");
  core.estimated_lcs = 209;
  EXPECT_NE(check_utilisation(core, top, 1.0).find("LUT6 sites"), std::string::npos);
  core.estimated_lcs = 200;
  core.lutram_luts = 8;  // distributed RAM counts: 208 sites
  EXPECT_EQ(check_utilisation(core, top, 1.0), "");
  core.lutram_luts = 12;
  EXPECT_NE(check_utilisation(core, top, 1.0).find("12 distributed RAM"), std::string::npos);
  core.lutram_luts = 0;
  core.estimated_lcs = 100;
  core.dsp48e1 = 2;  // e.g. operands widened before the multiply
  EXPECT_NE(check_utilisation(core, top, 1.0).find("2 DSP48E1"), std::string::npos);
  core.dsp48e1 = 1;
  top.dsp48e1 = 0;  // the multiplier fell into fabric
  EXPECT_NE(check_utilisation(core, top, 1.0).find("board top uses 0 DSP48E1"), std::string::npos);
  top.dsp48e1 = 1;
  core.estimated_lcs = 0;  // nothing parsed: never a pass
  EXPECT_NE(check_utilisation(core, top, 1.0), "");
}

// Captured from Yosys 0.23's `sta` on the measurement_sos core.
const char* const kSta = R"(
8. Executing STA pass (static timing analysis).
Warning: Module 'RAM32M' has no timing arcs!
Latest arrival time in 'iir_core' is 2759:
    2759 $auto$ff.cc:266:slice$7420 (FDRE.D)
           $auto$xilinx_dffopt.cc:347:execute$21072
)";

TEST(YosysSynthesis, ParsesYosysStaLatestArrival) {
  EXPECT_EQ(parse_sta_latest_arrival(kSta), 2759);
  EXPECT_FALSE(parse_sta_latest_arrival("No timing paths found.\n").has_value());
}

TEST(YosysSynthesis, ChecksTheEstimatedSlackOfEveryTop) {
  SynthesisResult r;
  r.set_name = "s";
  r.core.top = "iir_core";
  r.top.top = "basys3_top";
  EXPECT_NE(check_timing(r, 20).find("no register-to-register path"), std::string::npos);
  ClockEstimate c;
  c.clock = "clk_i";
  c.period_ps = 10000;
  c.worst_ps = 8000;
  c.slack_ps = 2000;  // exactly 20 %
  r.core.timing.clocks = {c};
  r.top.timing.clocks = {c};
  EXPECT_EQ(check_timing(r, 20), "");
  r.top.timing.clocks[0].slack_ps = 1999;
  const std::string failure = check_timing(r, 20);
  EXPECT_NE(failure.find("basys3_top (s), clock clk_i: estimated slack 1.999 ns is 19.99 %"),
            std::string::npos)
      << failure;
  EXPECT_EQ(failure.find("iir_core"), std::string::npos);
  r.top.timing.clocks[0].slack_ps = 2000;
  r.core.timing.types_without_model = {"MYSTERY"};
  EXPECT_NE(check_timing(r, 20).find("without a timing model break paths: MYSTERY"),
            std::string::npos);
}

// A result with one clock and one path per top, as the reports render it.
SynthesisResult small_result() {
  SynthesisResult r;
  r.set_name = "measurement_sos";
  r.core.top = "iir_core";
  r.top.top = "basys3_top";
  ClockEstimate c{"clk_i", 10000, 7500, 3000, 2500, 42};
  TimingPath p;
  p.clock = "clk_i";
  p.from = "q_rd_q[0]";
  p.to = "retransmit_q";
  p.to_pin = "FDRE D";
  p.steps = {{"$auto$1", "FDRE", "clock->Q", 303, "q_rd_q[0]", 20, 700},
             {"$abc$2", "LUT6", "I0->O", 642, "~retransmit_d", 1, 515}};
  p.cells_ps = 945;
  p.nets_ps = 1215;
  p.slack_ps = 10000 - 2160;
  p.logic_levels = 1;
  for (YosysRun* run : {&r.core, &r.top}) {
    run->timing.clocks = {c};
    run->timing.worst_paths = {p};
    run->yosys_sta_ps = 2759;
  }
  return r;
}

TEST(YosysSynthesis, ReportsSetTheEstimateBesideVivadosRoutedFigures) {
  ReportSettings settings;
  settings.command = "flange synth --coeffs coeffs/measurement_sos --out docs/synthesis.md";
  settings.max_core_lut_percent = 1.5;
  settings.min_slack_percent = 20;
  settings.vivado =
      read_vivado_report(std::string(FLANGE_SOURCE_DIR) + "/tests/data/vivado_report");
  const std::vector<SynthesisResult> results = {small_result()};
  const std::string md = synthesis_report_markdown(results, settings);
  EXPECT_NE(md.find("An estimate before place and route, not a timing sign-off."),
            std::string::npos);
  EXPECT_NE(
      md.find("| `measurement_sos` | `basys3_top` | `clk_i` | 42 | 3.00 | 7.50 | 2.50 | 25.0 % "
              "| 2.76 |"),
      std::string::npos)
      << md;
  EXPECT_NE(md.find("1. `q_rd_q[0]` -> `retransmit_q` (FDRE D): 2.16 ns"), std::string::npos) << md;
  EXPECT_NE(md.find("| worst setup slack (ns) | 2.50 | 3.412 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| worst path: from -> to | `q_rd_q[0]` -> `retransmit_q` | "
                    "`q_rd_q_reg[0]/C` -> `retransmit_q_reg/D` |"),
            std::string::npos)
      << md;

  const nlohmann::json j = nlohmann::json::parse(synthesis_report_json(results, settings));
  EXPECT_DOUBLE_EQ(j.at("vivado").at("wns_ns").get<double>(), 3.412);
  EXPECT_EQ(j.at("vivado").at("utilisation").at("slice_luts"), 702);
  const nlohmann::json& top = j.at("sets").at(0).at("tops").at("basys3_top").at("timing");
  EXPECT_DOUBLE_EQ(top.at("clocks").at(0).at("slack_percent").get<double>(), 25.0);
  EXPECT_EQ(top.at("worst_paths").at(0).at("steps").at(1).at("net"), "~retransmit_d");
  EXPECT_TRUE(j.at("checks").at("pass").get<bool>());
}

}  // namespace
}  // namespace flange::tb
