// SPDX-License-Identifier: MIT
// `flange --version`: the version, the commit, the data folder and the tools, one per line.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <sstream>

#include "flange_in_process.h"
#include "version.h"

namespace flange::cli {
namespace {

using testing::run_flange_captured;

TEST(VersionCommand, PrintsVersionCommitDataFolderAndTools) {
  const testing::FlangeOutcome outcome = run_flange_captured({"--version"});
  EXPECT_EQ(outcome.status, kExitOk) << outcome.err;
  const std::regex lines(
      "flange " + runtime::version() +
      "\ncommit: not recorded \\(not the flange executable\\)\ndata: .+ "
      "\\((source tree|installed|FLANGE_DATA_DIR)\\)\nverilator: .+\nyosys: .+\n");
  EXPECT_TRUE(std::regex_match(outcome.out, lines)) << outcome.out;
}

TEST(VersionCommand, GeneratedFilesNameTheVersion) {
  const testing::FlangeOutcome design = run_flange_captured(
      {"design", "--fs", "6", "--order", "2", "--fc", "0.5", "--no-plot", "--out",
       std::string(FLANGE_BINARY_DIR) + "/test_files/version_command_design"});
  ASSERT_EQ(design.status, kExitOk) << design.err;
  std::ifstream json(std::string(FLANGE_BINARY_DIR) +
                     "/test_files/version_command_design/filter.json");
  std::stringstream text;
  text << json.rdbuf();
  EXPECT_NE(text.str().find("\"generated_by\": \"flange design --fs 6 --order 2 --fc 0.5 "
                            "--no-plot (flange " +
                            runtime::version() + ")\""),
            std::string::npos)
      << text.str().substr(0, 300);
}

}  // namespace
}  // namespace flange::cli
