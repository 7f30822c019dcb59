// SPDX-License-Identifier: MIT
// Vivado's reports read from hand-written samples in its documented layout
// (tests/data/vivado_report/), and the one-line errors on reports that are not in it.
#include "vivado_report.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "test_files.h"

namespace flange::tb {
namespace {

namespace fs = std::filesystem;
const fs::path kSamples = fs::path(FLANGE_SOURCE_DIR) / "tests/data/vivado_report";

std::string sample(const char* name) {
  std::ifstream in(kSamples / name);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The message of the VivadoReportError that parsing `text` as a timing summary throws.
std::string timing_error(const std::string& text) {
  try {
    parse_timing_summary(text, "t.rpt");
  } catch (const VivadoReportError& e) {
    return e.what();
  }
  return "no error";
}

TEST(VivadoReport, ReadsTheTimingSummary) {
  const VivadoTiming t = parse_timing_summary(sample("timing_summary.rpt"), "t.rpt");
  EXPECT_DOUBLE_EQ(t.wns_ns, 3.412);
  EXPECT_DOUBLE_EQ(t.tns_ns, 0.0);
  EXPECT_EQ(t.failing_endpoints, 0);
  EXPECT_EQ(t.total_endpoints, 1471);
  ASSERT_TRUE(t.whs_ns.has_value());
  EXPECT_DOUBLE_EQ(*t.whs_ns, 0.118);
  ASSERT_EQ(t.clocks.size(), 1u);
  EXPECT_EQ(t.clocks[0].name, "sys_clk_pin");
  EXPECT_DOUBLE_EQ(t.clocks[0].period_ns, 10.0);
  ASSERT_TRUE(t.clocks[0].wns_ns.has_value());
  EXPECT_DOUBLE_EQ(*t.clocks[0].wns_ns, 3.412);
  ASSERT_TRUE(t.worst_path.has_value());
  EXPECT_DOUBLE_EQ(t.worst_path->slack_ns, 3.412);
  EXPECT_EQ(t.worst_path->source, "q_rd_q_reg[0]/C");
  EXPECT_EQ(t.worst_path->destination, "retransmit_q_reg/D");
  EXPECT_DOUBLE_EQ(t.worst_path->data_path_ns, 6.529);
  EXPECT_DOUBLE_EQ(t.worst_path->logic_ns, 1.712);
  EXPECT_DOUBLE_EQ(t.worst_path->route_ns, 4.817);
  EXPECT_EQ(t.worst_path->logic_levels, 6);
}

TEST(VivadoReport, ReadsTheUtilisation) {
  const VivadoUtilisation u = parse_utilization(sample("utilization.rpt"), "u.rpt");
  EXPECT_EQ(u.device, "7a35tcpg236-1");
  EXPECT_EQ(u.slice_luts, 702);
  EXPECT_EQ(u.slice_registers, 566);
  EXPECT_EQ(u.lut_as_memory, 80);
  EXPECT_EQ(u.f7_muxes, 8);
  EXPECT_EQ(u.dsps, 1);
  EXPECT_EQ(u.bonded_iob, 48);
  ASSERT_TRUE(u.block_ram_tiles.has_value());
  EXPECT_DOUBLE_EQ(*u.block_ram_tiles, 0.0);
}

TEST(VivadoReport, NamesFileLineAndFieldOfABadReport) {
  std::string text = sample("timing_summary.rpt");
  const std::size_t row = text.find("      3.412        0.000");
  ASSERT_NE(row, std::string::npos);
  std::string bad = text;
  bad.replace(row, 11, "      abc  ");
  EXPECT_EQ(timing_error(bad), "t.rpt:62: field WNS(ns): \"abc\" is not a number");
  bad = text;
  bad.replace(row, 11, "         NA");
  EXPECT_NE(timing_error(bad).find("t.rpt:62: field WNS(ns): NA"), std::string::npos);
  bad = text;
  bad.replace(row, 24, "      3.412");  // one value short
  EXPECT_EQ(timing_error(bad),
            "t.rpt:62: the \"Design Timing Summary\" row has 11 values for 12 "
            "columns");
  bad = text;
  bad.replace(text.find("| Design Timing Summary"), 22, "| Something Else");
  EXPECT_NE(timing_error(bad).find("no \"Design Timing Summary\" table"), std::string::npos);
  EXPECT_EQ(timing_error(""), "t.rpt:1: the file is empty");

  std::string util = sample("utilization.rpt");
  util.replace(util.find("| Slice Registers         |  566"), 32,
               "| Slice Registers         |  5x6");
  try {
    parse_utilization(util, "u.rpt");
    FAIL() << "a bad Used figure";
  } catch (const VivadoReportError& e) {
    EXPECT_EQ(std::string(e.what()),
              "u.rpt:32: field Slice Registers Used: \"5x6\" is not a number");
  }
}

TEST(VivadoReport, ReadsAFolderAndNamesAMissingFile) {
  const VivadoReport r = read_vivado_report(kSamples);
  EXPECT_DOUBLE_EQ(r.timing.wns_ns, 3.412);
  EXPECT_EQ(r.utilisation.slice_luts, 702);
  const fs::path empty = flange::testing::fresh_test_dir("vivado_report_missing");
  try {
    read_vivado_report(empty);
    FAIL() << "no reports in the folder";
  } catch (const VivadoReportMissing& e) {
    EXPECT_NE(std::string(e.what()).find("timing_summary.rpt: cannot be read"), std::string::npos);
  }
}

}  // namespace
}  // namespace flange::tb
