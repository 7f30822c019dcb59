// SPDX-License-Identifier: MIT
// The thesis filters of `flange demo` are the sets checked in under coeffs/.
#include "thesis_filters.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "version.h"

namespace flange::coeffs {
namespace {

TEST(ThesisFilters, DemoCommandsMatchTheCheckedInSets) {
  for (const ThesisFilter& filter : thesis_filters()) {
    const std::filesystem::path dir =
        std::filesystem::path(FLANGE_SOURCE_DIR) / "coeffs" / filter.set_name;
    if (filter.expect_rejected) {
      EXPECT_FALSE(std::filesystem::exists(dir)) << filter.set_name << " must not be checked in";
      continue;
    }
    std::ifstream file(dir / "filter.json");
    ASSERT_TRUE(file) << dir << " is missing; run bash coeffs/regenerate.sh";
    const nlohmann::json json = nlohmann::json::parse(file);
    std::string command = "flange";
    for (const std::string& arg : filter.design) command += " " + arg;
    EXPECT_EQ(json["generated_by"].get<std::string>(), runtime::generated_by(command))
        << "coeffs/src/thesis_filters.cpp and coeffs/regenerate.sh disagree on " << filter.set_name;
  }
}

}  // namespace
}  // namespace flange::coeffs
