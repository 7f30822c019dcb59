// SPDX-License-Identifier: MIT
// The version every generated file names, and the tool versions `flange --version` prints.
#include "version.h"

#include <gtest/gtest.h>

#include <regex>

namespace flange::runtime {
namespace {

TEST(Version, IsTheProjectVersion) {
  EXPECT_TRUE(std::regex_match(version(), std::regex(R"(\d+\.\d+\.\d+)"))) << version();
}

TEST(Version, GeneratedByNamesTheCommandAndTheVersion) {
  EXPECT_EQ(generated_by("flange design --fs 6"),
            "flange design --fs 6 (flange " + version() + ")");
  EXPECT_EQ(generated_by(std::vector<std::string>{"simulate", "--seed", "3"}),
            "flange simulate --seed 3 (flange " + version() + ")");
}

TEST(Version, ToolVersionIsTheFirstLineOrNotFound) {
  EXPECT_EQ(tool_version({"sh", "-c", "echo 'Tool 1.2'; echo more"}), "Tool 1.2");
  EXPECT_EQ(tool_version({"flange-no-such-program", "--version"}), "not found");
  EXPECT_EQ(tool_version({"sh", "-c", "echo 'Tool 1.2'; exit 3"}), "not found");
}

}  // namespace
}  // namespace flange::runtime
