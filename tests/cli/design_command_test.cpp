// SPDX-License-Identifier: MIT
// `flange design` as a user runs it: exit statuses, one-line errors, the files it writes.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli.h"
#include "flange_in_process.h"

namespace flange::cli {
namespace {

using testing::FlangeOutcome;
using testing::run_flange_captured;

namespace fs = std::filesystem;

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::path(FLANGE_BINARY_DIR) / "test_design_command" / name;
  fs::remove_all(dir);
  return dir;
}

std::vector<std::string> with_out(std::vector<std::string> args, const fs::path& dir) {
  args.push_back("--out");
  args.push_back(dir.string());
  return args;
}

struct BadInput {
  std::vector<std::string> args;
  std::string names;  // the argument the one-line message must name
};

TEST(DesignCommand, EveryBadInputExitsTwoWithOneLineAndNoFiles) {
  const std::vector<BadInput> cases = {
      {{"--fs", "6", "--fp", "1", "--fa", "0.9", "--ap", "0.17", "--aa", "40"}, "--fp"},
      {{"--fs", "6", "--fp", "1", "--fa", "1", "--ap", "0.17", "--aa", "40"}, "--fp"},
      {{"--fs", "100", "--fp", "10", "--fa", "50", "--ap", "0.1737", "--aa", "40"}, "--fa"},
      {{"--fs", "100", "--fp", "10", "--fa", "70", "--ap", "0.1737", "--aa", "40"}, "--fa"},
      {{"--fs", "6", "--fp", "0.2", "--fa", "1", "--ap", "40", "--aa", "40"}, "--ap"},
      {{"--fs", "6", "--fp", "0.2", "--fa", "1", "--ap", "3", "--aa", "1"}, "--ap"},
      {{"--fs", "0", "--order", "5", "--fc", "1"}, "--fs"},
      {{"--fs", "-6", "--order", "5", "--fc", "1"}, "--fs"},
      {{"--fs", "nan", "--order", "5", "--fc", "1"}, "--fs"},
      {{"--fs", "inf", "--order", "5", "--fc", "1"}, "--fs"},
      {{"--fs", "6", "--order", "5", "--fc", "0"}, "--fc"},
      {{"--fs", "6", "--order", "5", "--fc", "-1"}, "--fc"},
      {{"--fs", "6", "--order", "5", "--fc", "nan"}, "--fc"},
      {{"--fs", "6", "--order", "5", "--fc", "3"}, "--fc"},
      {{"--fs", "6", "--order", "0", "--fc", "1"}, "--order"},
      {{"--fs", "6", "--order", "33", "--fc", "1"}, "--order"},
      {{"--fs", "6", "--order", "-2", "--fc", "1"}, "--order"},
      {{"--fs", "6", "--order", "five", "--fc", "1"}, "--order"},
      {{"--fs", "6", "--fp", "0", "--fa", "1", "--ap", "0.17", "--aa", "40"}, "--fp"},
      {{"--fs", "6", "--fp", "0.2", "--fa", "1", "--ap", "0", "--aa", "40"}, "--ap"},
      {{"--fs", "6", "--fp", "0.2", "--fa", "1", "--ap", "0.1", "--aa", "inf"}, "--aa"},
      {{"--fs", "6", "--fp", "0.2", "--fa", "1"}, "--fp --fa --ap --aa"},
      {{"--fs", "6", "--order", "5"}, "--order --fc"},
      {{"--order", "5", "--fc", "1"}, "--fs"},
      {{"--fs", "6"}, "--order --fc"},
      {{"--fs", "6", "--order", "5", "--fc", "1", "--structure", "lattice"}, "--structure"},
      {{"--fs", "6", "--order", "5", "--fc", "1", "--coef-bits", "3"}, "--coef-bits"},
      {{"--fs", "6", "--order", "5", "--fc", "1", "--data-bits", "30"}, "--data-bits"},
      {{"--fs", "6", "--order", "5", "--fc", "1", "--acc-bits", "80"}, "--acc-bits"},
      {{"--fs", "6", "--fp", "0.001", "--fa", "0.0011", "--ap", "0.1", "--aa", "120"},
       "--fp --fa --ap --aa"},
  };
  for (const BadInput& bad : cases) {
    SCOPED_TRACE(bad.names);
    const fs::path dir = fresh_dir("bad");
    std::vector<std::string> args{"design"};
    args.insert(args.end(), bad.args.begin(), bad.args.end());
    const FlangeOutcome outcome = run_flange_captured(with_out(args, dir));
    std::string joined;
    for (const std::string& arg : bad.args) joined += arg + " ";
    EXPECT_EQ(outcome.status, kExitBadArgument) << joined << "\n" << outcome.err;
    EXPECT_EQ(std::count(outcome.err.begin(), outcome.err.end(), '\n'), 1) << joined << outcome.err;
    EXPECT_NE(outcome.err.find(bad.names), std::string::npos)
        << joined << ": message does not name " << bad.names << ": " << outcome.err;
    EXPECT_FALSE(fs::exists(dir)) << joined;
  }
}

TEST(DesignCommand, ValueOfTheWrongTypeNamesTheValidRange) {
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--fs", "6", "--order", "1.5", "--fc", "1"},
       "--order: '1.5' is not a valid value; expected "
       "filter order (1 to 32)"},
      {{"--fs", "abc", "--order", "5", "--fc", "1"},
       "--fs: 'abc' is not a valid value; expected "
       "sample rate in Hz (> 0)"},
      {{"--fs", "6", "--order", "5", "--fc", "1", "--coef-bits", "x"},
       "--coef-bits: 'x' is not a valid value; expected coefficient width (4 to 32)"},
  };
  for (const auto& [args, message] : cases) {
    const fs::path dir = fresh_dir("bad_type");
    std::vector<std::string> full{"design"};
    full.insert(full.end(), args.begin(), args.end());
    const FlangeOutcome outcome = run_flange_captured(with_out(full, dir));
    EXPECT_EQ(outcome.status, kExitBadArgument) << outcome.err;
    EXPECT_NE(outcome.err.find(message), std::string::npos) << outcome.err;
    EXPECT_EQ(std::count(outcome.err.begin(), outcome.err.end(), '\n'), 1) << outcome.err;
  }
}

TEST(DesignCommand, UnstableDirectFormExitsThreeAndWritesNothing) {
  const fs::path dir = fresh_dir("vehicle_df1");
  const FlangeOutcome outcome = run_flange_captured(with_out(
      {"design", "--fs", "100", "--order", "7", "--fc", "0.259", "--structure", "df1"}, dir));
  EXPECT_EQ(outcome.status, 3);
  EXPECT_EQ(std::count(outcome.err.begin(), outcome.err.end(), '\n'), 1) << outcome.err;
  EXPECT_NE(outcome.err.find("outside the unit circle (max |z| = "), std::string::npos)
      << outcome.err;
  EXPECT_NE(outcome.err.find("use --structure sos or more coefficient bits"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir));
}

TEST(DesignCommand, ThesisPrintedVehicleCoefficientsAreRefusedAsUnstable) {
  // Eq. 4.20 as printed: 4 significant digits of a 7th-order direct form.
  const fs::path dir = fresh_dir("eq420");
  const FlangeOutcome outcome = run_flange_captured(
      with_out({"design", "--fs", "100", "--tf-b",
                "2.273e-15,1.591e-14,4.773e-14,7.955e-14,7.955e-14,4.773e-14,1.591e-14,2.273e-15",
                "--tf-a", "1,-6.927,20.56,-33.92,33.56,-19.93,6.574,-0.9295"},
               dir));
  EXPECT_EQ(outcome.status, 3) << outcome.err;
  EXPECT_NE(outcome.err.find("unstable before any quantisation"), std::string::npos) << outcome.err;
  EXPECT_FALSE(fs::exists(dir));
}

TEST(DesignCommand, MissedSpecExitsThree) {
  // The thesis's 5th-order measurement filter checked against the thesis's own spec.
  const fs::path dir = fresh_dir("missed_spec");
  const FlangeOutcome outcome =
      run_flange_captured(with_out({"design", "--fs", "6", "--order", "5", "--fc", "0.5742", "--fp",
                                    "0.21128", "--fa", "0.975", "--ap", "0.1737", "--aa", "40"},
                                   dir));
  EXPECT_EQ(outcome.status, 3);
  EXPECT_NE(outcome.err.find("stopband attenuation"), std::string::npos) << outcome.err;
  EXPECT_FALSE(fs::exists(dir));
}

TEST(DesignCommand, SpecDesignWritesEveryOutput) {
  const fs::path dir = fresh_dir("spec");
  const FlangeOutcome outcome = run_flange_captured(with_out(
      {"design", "--fs", "6", "--fp", "0.21128", "--fa", "0.975", "--ap", "0.1737", "--aa", "40"},
      dir));
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  for (const char* file : {"filter.json", "coeffs.mem", "iir_coeffs_pkg.sv", "response.svg"}) {
    ASSERT_TRUE(fs::exists(dir / file)) << file;
    std::ifstream in(dir / file);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(text.find("NaN"), std::string::npos) << file;
    EXPECT_NE(text.find("generated"), std::string::npos) << file;
  }
  std::ifstream in(dir / "filter.json");
  const nlohmann::json json = nlohmann::json::parse(in);
  for (const char* key : {"fs_hz", "order", "fc_hz", "b", "a", "zeros", "poles", "gain", "sos",
                          "spec", "quantized"}) {
    EXPECT_TRUE(json.contains(key)) << key;
  }
  EXPECT_EQ(json["order"], 4);
  const auto& q = json["quantized"];
  for (const char* key :
       {"structure", "coef_bits", "coef_frac_bits", "data_bits", "acc_bits", "words",
        "max_pole_radius", "stable", "passband_loss_db", "stopband_atten_db"}) {
    EXPECT_TRUE(q.contains(key)) << key;
  }
  EXPECT_EQ(q["structure"], "sos");
  EXPECT_TRUE(q["stable"].get<bool>());
  EXPECT_LE(q["passband_loss_db"].get<double>(), 0.1737 + 0.01);
  EXPECT_GE(q["stopband_atten_db"].get<double>(), 40.0 - 0.01);

  // The ROM image holds the words in order, two comment lines first.
  std::ifstream mem(dir / "coeffs.mem");
  std::string line;
  std::vector<std::string> words;
  while (std::getline(mem, line)) {
    if (line.rfind("//", 0) != 0) words.push_back(line);
  }
  ASSERT_EQ(words.size(), q["words"].size());
  for (std::size_t i = 0; i < words.size(); ++i) {
    const std::int64_t word = q["words"][i];
    const std::int64_t mask = (std::int64_t{1} << 18) - 1;
    EXPECT_EQ(std::stoll(words[i], nullptr, 16), word & mask) << i;
    EXPECT_EQ(words[i].size(), 5u);
  }
}

TEST(DesignCommand, HelpExitsZero) {
  const FlangeOutcome outcome = run_flange_captured({"design", "--help"});
  EXPECT_EQ(outcome.status, 0);
  EXPECT_NE(outcome.out.find("--coef-bits"), std::string::npos);
}

TEST(DesignCommand, UnknownSubcommandExitsTwo) {
  const FlangeOutcome outcome = run_flange_captured({"frobnicate"});
  EXPECT_EQ(outcome.status, kExitBadArgument);
}

}  // namespace
}  // namespace flange::cli
