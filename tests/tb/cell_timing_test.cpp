// SPDX-License-Identifier: MIT
// The cell models read from Yosys's RTLIL (tests/data/synth/cell_models.il, cut down from Yosys
// 0.23's write_rtlil of the xc7 cells after `sta`).
#include "cell_timing.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace flange::tb {
namespace {

std::string models_text() {
  std::ifstream in(std::string(FLANGE_SOURCE_DIR) + "/tests/data/synth/cell_models.il");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(CellTiming, NormalisesParameterValues) {
  EXPECT_EQ(cell_parameter_value("00000000000000000000000000000001"), "1");     // Yosys JSON
  EXPECT_EQ(cell_parameter_value("32'00000000000000000000000000000001"), "1");  // RTLIL
  EXPECT_EQ(cell_parameter_value("1"), "1");                                    // RTLIL decimal
  EXPECT_EQ(cell_parameter_value("2"), "10");
  EXPECT_EQ(cell_parameter_value("0"), "0");
  EXPECT_EQ(cell_parameter_value("\"DIRECT\""), "DIRECT");
  EXPECT_EQ(cell_parameter_value("DIRECT "), "DIRECT");  // JSON marks strings with a space
  EXPECT_EQ(cell_parameter_value("4'0000"), "0");
}

TEST(CellTiming, ReadsArcsSetupAndClockToOutput) {
  const CellTimingLibrary library = CellTimingLibrary::parse(models_text());
  ASSERT_EQ(library.cells().size(), 3u);
  const CellTiming* lut = library.find("LUT2", {{"INIT", "110"}});
  ASSERT_NE(lut, nullptr);
  ASSERT_EQ(lut->comb.at("I0[0]").size(), 1u);
  EXPECT_EQ(lut->comb.at("I0[0]")[0].to, "O[0]");
  EXPECT_EQ(lut->comb.at("I0[0]")[0].ps, 238);
  EXPECT_EQ(lut->comb.at("I1[0]")[0].ps, 127);  // the worse of rise (120) and fall (127)
  EXPECT_EQ(lut->inputs, (std::set<std::string>{"I0", "I1"}));

  const CellTiming* ff = library.find("FDRE", {});
  ASSERT_NE(ff, nullptr);
  EXPECT_EQ(ff->clock_to_out.at("Q[0]"), 303);
  EXPECT_EQ(ff->clock_of_output.at("Q[0]"), "C");
  EXPECT_EQ(ff->setup.at("D[0]"), 0);  // an endpoint even with no setup time
  EXPECT_EQ(ff->setup.at("R[0]"), 404);
  EXPECT_EQ(ff->clock_of_input.at("R[0]"), "C");
  EXPECT_FALSE(ff->setup.count("CE[0]"));
  EXPECT_TRUE(ff->comb.empty());  // the process's logic is no arc

  const CellTiming* carry = library.find("CARRY4", {});
  ASSERT_NE(carry, nullptr);
  EXPECT_EQ(carry->comb.at("CI[0]")[0].to, "CO[3]");
  // A full arc from a concatenation: {S[1], DI[0]} to each of O[3:0].
  ASSERT_EQ(carry->comb.at("S[1]").size(), 4u);
  ASSERT_EQ(carry->comb.at("DI[0]").size(), 4u);
  EXPECT_EQ(carry->comb.at("DI[0]")[3].to, "O[3]");
  EXPECT_EQ(carry->comb.at("DI[0]")[3].ps, 500);
  EXPECT_EQ(library.find("DSP48E1", {}), nullptr);
}

TEST(CellTiming, PrefersTheModuleElaboratedForTheParameters) {
  std::string text = models_text();
  // A second FDRE, elaborated for IS_C_INVERTED = 1 with a slower clock-to-output.
  const std::string second =
      "module $paramod\\FDRE\\IS_C_INVERTED=1'1\n  parameter \\IS_C_INVERTED 1'1\n"
      "  wire input 1 \\C\n  wire input 2 \\D\n  wire output 3 \\Q\n"
      "  cell $specify3 $s\n    parameter signed \\T_FALL_MAX 400\n"
      "    parameter signed \\T_RISE_MAX 400\n    connect \\DST \\Q\n    connect \\SRC \\C\n"
      "  end\nend\n";
  const CellTimingLibrary library = CellTimingLibrary::parse(text + second);
  EXPECT_EQ(library.find("FDRE", {{"IS_C_INVERTED", "1"}})->clock_to_out.at("Q[0]"), 400);
  EXPECT_EQ(library.find("FDRE", {{"IS_C_INVERTED", "0"}})->clock_to_out.at("Q[0]"), 303);
  // Neither agrees and their arcs differ: no model rather than a guess.
  EXPECT_EQ(library.find("FDRE", {{"INIT", "1"}, {"IS_C_INVERTED", "10"}}), nullptr);
}

TEST(CellTiming, RejectsTextThatIsNotCellModels) {
  EXPECT_THROW(CellTimingLibrary::parse("module \\A\n  cell $specify2 $s\n"), CellTimingError);
  EXPECT_THROW(CellTimingLibrary::parse("end\n"), CellTimingError);
  try {
    CellTimingLibrary::parse(
        "module \\A\n  wire input 1 \\I\n  cell $specify2 $s\n    parameter \\FULL 1'0\n"
        "    connect \\SRC \\I\n    connect \\DST \\O\n  end\nend\n");
    FAIL() << "an arc to a wire the module lacks";
  } catch (const CellTimingError& e) {
    EXPECT_NE(std::string(e.what()).find("line 3"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("O is not a wire"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace flange::tb
