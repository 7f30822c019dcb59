// SPDX-License-Identifier: MIT
// `flange synth`: the parsing of Yosys's report and the checks, on hand-written reports (the
// Yosys run itself is the FlangeSynth.* CTest test, tests/cli/CMakeLists.txt).
#include "yosys_synthesis.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace flange::tb
