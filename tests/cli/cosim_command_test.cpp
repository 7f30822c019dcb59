// SPDX-License-Identifier: MIT
// `flange cosim`: a clean run ends with the one summary line and status 0; a model that disagrees
// with the RTL's ROM gives status 1 and the first mismatch; bad input gives status 2 and one line
// naming the file and field. The first run builds the set's runner (about 15-25 s).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "cli.h"
#include "flange_in_process.h"

namespace flange::cli {
namespace {

using testing::FlangeOutcome;
using testing::run_flange_captured;
namespace fs = std::filesystem;

const fs::path kSet = fs::path(FLANGE_SOURCE_DIR) / "coeffs" / "measurement_sos";

std::string last_line(const std::string& text) {
  std::string t = text;
  while (!t.empty() && t.back() == '\n') t.pop_back();
  return t.substr(t.rfind('\n') == std::string::npos ? 0 : t.rfind('\n') + 1);
}

TEST(CosimCommand, CleanRunEndsWithTheSummary) {
  const FlangeOutcome r =
      run_flange_captured({"cosim", "--coeffs", (kSet / "filter.json").string(), "--samples",
                           "3000", "--seed", "5", "--stimulus", "fullscale"});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(last_line(r.out),
            "cosim: 3000 samples, 0 mismatches, 40 cycles/sample, 40 cycles latency")
      << r.out << r.err;
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << "exactly one line: " << r.out;
}

TEST(CosimCommand, TwelveChannelsTakeTheSamplesInTurn) {
  const fs::path set = fs::path(FLANGE_SOURCE_DIR) / "tests/data/coeffs/loco_ch12/filter.json";
  const FlangeOutcome r = run_flange_captured(
      {"cosim", "--coeffs", set.string(), "--samples", "2400", "--stimulus", "fullscale"});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(last_line(r.out),
            "cosim: 2400 samples, 0 mismatches, 52 cycles/sample, 52 cycles latency, 12 channels "
            "in turn")
      << r.out << r.err;
}

TEST(CosimCommand, MismatchFailsWithTheFirstOne) {
  // The same package and ROM image, but the model reads one coefficient off by one LSB of its hi
  // word (word 2M + 1 = 5: H_b[0] of section 0; a lo word's LSB weighs 2^-17 of that and may
  // never show in 500 samples).
  const fs::path dir = fs::temp_directory_path() / "flange_cosim_mismatch";
  fs::remove_all(dir);
  fs::create_directories(dir);
  for (const char* f : {"iir_coeffs_pkg.sv", "coeffs.mem"}) fs::copy_file(kSet / f, dir / f);
  std::ifstream in(kSet / "filter.json");
  nlohmann::json j = nlohmann::json::parse(in);
  j["quantized"]["words"][5] = j["quantized"]["words"][5].get<int>() + 1;
  std::ofstream(dir / "filter.json") << j.dump(1);

  const FlangeOutcome r = run_flange_captured(
      {"cosim", "--coeffs", (dir / "filter.json").string(), "--samples", "500"});
  EXPECT_EQ(r.status, 1) << r.out << r.err;
  EXPECT_TRUE(std::regex_search(
      r.err, std::regex("first mismatch: cycle [0-9]+, sample [0-9]+ \\(input -?[0-9]+\\): dut "
                        "sample_o=-?[0-9]+ .* \\| model sample_o=")))
      << r.err;
  EXPECT_TRUE(std::regex_match(last_line(r.out),
                               std::regex("cosim: 500 samples, [1-9][0-9]* mismatches, 40 "
                                          "cycles/sample, 40 cycles latency")))
      << r.out;
  fs::remove_all(dir);
}

TEST(CosimCommand, BadInputIsOneLineNamingFileAndField) {
  const fs::path bad = fs::temp_directory_path() / "flange_cosim_bad.json";
  std::ofstream(bad) << R"({"quantized": {"data_bits": "16"}})";
  const FlangeOutcome r = run_flange_captured({"cosim", "--coeffs", bad.string()});
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find(bad.string()), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("quantized.data_bits"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  fs::remove(bad);

  const FlangeOutcome s = run_flange_captured(
      {"cosim", "--coeffs", (kSet / "filter.json").string(), "--stimulus", "x"});
  EXPECT_EQ(s.status, 2);
  EXPECT_NE(s.err.find("--stimulus 'x'"), std::string::npos) << s.err;
}

}  // namespace
}  // namespace flange::cli
