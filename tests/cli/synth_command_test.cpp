// SPDX-License-Identifier: MIT
// `flange synth`: a Vivado report folder that is missing or does not parse is refused in one
// line before Yosys runs (exit 1 and 2, cli/README.md).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "cli.h"
#include "test_files.h"

namespace flange::cli {
namespace {

namespace fs = std::filesystem;

int synth(const std::vector<std::string>& args, std::string& err) {
  std::ostringstream out, err_stream;
  std::vector<std::string> all = {"synth"};
  all.insert(all.end(), args.begin(), args.end());
  const int status = run_flange(all, out, err_stream);
  err = err_stream.str();
  return status;
}

TEST(SynthCommand, RefusesAMissingOrBadVivadoReportInOneLine) {
  const fs::path dir = flange::testing::fresh_test_dir("synth_vivado_report");
  std::string err;
  EXPECT_EQ(
      synth({"--vivado-report", (dir / "none").string(), "--out", (dir / "r.md").string()}, err),
      kExitFailure);
  EXPECT_NE(err.find("none/timing_summary.rpt: cannot be read"), std::string::npos) << err;
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;

  const fs::path samples = fs::path(FLANGE_SOURCE_DIR) / "tests/data/vivado_report";
  std::ifstream in(samples / "timing_summary.rpt");
  std::ostringstream text;
  text << in.rdbuf();
  std::string bad = text.str();
  bad.replace(bad.find("      3.412        0.000"), 11, "      3,412");
  fs::create_directories(dir / "bad");
  flange::testing::write_file(dir / "bad" / "timing_summary.rpt", bad);
  fs::copy_file(samples / "utilization.rpt", dir / "bad" / "utilization.rpt");
  EXPECT_EQ(
      synth({"--vivado-report", (dir / "bad").string(), "--out", (dir / "r.md").string()}, err),
      kExitBadArgument);
  EXPECT_NE(err.find("bad/timing_summary.rpt:62: field WNS(ns): \"3,412\" is not a number"),
            std::string::npos)
      << err;
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
  EXPECT_FALSE(fs::exists(dir / "r.md"));  // refused before any report is written
}

}  // namespace
}  // namespace flange::cli
