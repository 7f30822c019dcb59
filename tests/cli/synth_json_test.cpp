// SPDX-License-Identifier: MIT
// The JSON that FlangeSynth.MeasurementSosDspLutShareAndSlack wrote (its CTest fixture: no second
// Yosys run) holds what docs/synthesis.md promises: every top's slack, five worst paths named by
// RTL signals, each the sum of its steps.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

namespace {

namespace fs = std::filesystem;

TEST(SynthJson, NamesEveryTopsSlackAndWorstPathsByRtlNames) {
  const fs::path path = fs::path(FLANGE_BINARY_DIR) / "synthesis" / "measurement_sos.json";
  std::ifstream in(path);
  ASSERT_TRUE(in) << path << " is missing: run FlangeSynth.MeasurementSosDspLutShareAndSlack";
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_TRUE(j.at("checks").at("pass").get<bool>()) << j.at("checks").at("failures");
  EXPECT_DOUBLE_EQ(j.at("net_allowance").at("base_ns").get<double>(), 0.5);
  const nlohmann::json& tops = j.at("sets").at(0).at("tops");
  for (const char* top : {"iir_core", "basys3_top"}) {
    SCOPED_TRACE(top);
    const nlohmann::json& timing = tops.at(top).at("timing");
    ASSERT_EQ(timing.at("clocks").size(), 1u);
    const nlohmann::json& clock = timing.at("clocks").at(0);
    EXPECT_NEAR(clock.at("slack_ns").get<double>(), 10.0 - clock.at("worst_ns").get<double>(),
                1e-9);
    EXPECT_GE(clock.at("slack_percent").get<double>(), 20.0);
    EXPECT_LT(clock.at("cells_only_ns").get<double>(), clock.at("worst_ns").get<double>());
    const nlohmann::json& paths = timing.at("worst_paths");
    ASSERT_EQ(paths.size(), 5u);
    EXPECT_NEAR(paths.at(0).at("total_ns").get<double>(), clock.at("worst_ns").get<double>(), 1e-9);
    for (std::size_t i = 0; i < paths.size(); ++i) {
      const std::string from = paths[i].at("from"), to = paths[i].at("to");
      EXPECT_NE(from.front(), '$') << from;  // an RTL name, not a Yosys cell id
      EXPECT_NE(to.front(), '$') << to;
      if (i > 0) {
        EXPECT_GE(paths[i - 1].at("total_ns").get<double>(), paths[i].at("total_ns").get<double>());
      }
      double sum = paths[i].at("setup_ns");
      for (const nlohmann::json& step : paths[i].at("steps"))
        sum += step.at("cell_ns").get<double>() + step.at("net_ns").get<double>();
      EXPECT_NEAR(sum, paths[i].at("total_ns").get<double>(), 1e-9);
    }
  }
}

}  // namespace
