// SPDX-License-Identifier: MIT
// `flange calibrate` as a user runs it: fit, append and refit, the model file, bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "calibration.h"
#include "cli.h"
#include "flange_in_process.h"
#include "input_error.h"
#include "test_files.h"

namespace flange::cli {
namespace {

using testing::FlangeOutcome;
using testing::run_flange_captured;

using host::Calibration;
using host::InputError;
using host::load_calibration;
using testing::fresh_test_dir;
using testing::write_file;

// Bench-like rows whose voltage is eq. 3.14 inverted (no noise): steps of clearance while the
// temperature sweeps.
std::string bench_rows(int count, double t0, const std::string& run) {
  std::ostringstream text;
  for (int k = 0; k < count; ++k) {
    const double d = 1.5 + 8.0 * (k % 40) / 39.0;
    const double temp = 20.0 + 78.0 * (k % 53) / 52.0;
    const double a = 0.05812, b = 0.3672 + 0.0006618 * temp, c = 1.16 - 0.0036 * temp - d;
    const double v = (-b + std::sqrt(b * b - 4 * a * c)) / (2 * a);
    text << t0 + k / 6.0 << "," << d << "," << temp << "," << v << (run.empty() ? "" : ",") << run
         << "\n";
  }
  return text.str();
}

TEST(CalibrateCommand, FitsAppendsAndRefits) {
  const auto dir = fresh_test_dir("calibrate");
  const auto db =
      write_file(dir / "db.csv", "t_s,clearance_mm,temp_c,voltage_v\n" + bench_rows(400, 0.0, ""));
  const auto session = write_file(dir / "day2.csv",
                                  "t_s,clearance_mm,temp_c,voltage_v\n" + bench_rows(100, 0.0, ""));
  const auto model = dir / "model.json";
  FlangeOutcome first =
      run_flange_captured({"calibrate", "--data", db.string(), "--out", model.string()});
  ASSERT_EQ(first.status, 0) << first.err;
  EXPECT_NE(first.out.find("<- selected"), std::string::npos);
  Calibration loaded = load_calibration(model.string());
  EXPECT_EQ(loaded.fit.model.order(), 2);
  EXPECT_NEAR(loaded.fit.model.clearance_mm(4.0, 50.0),
              1.16 + 0.3672 * 4 - 0.0036 * 50 + 0.05812 * 16 + 0.0006618 * 200, 1e-6);

  FlangeOutcome second = run_flange_captured(
      {"calibrate", "--data", db.string(), "--append", session.string(), "--out", model.string()});
  ASSERT_EQ(second.status, 0) << second.err;
  std::ifstream in(model);
  const nlohmann::json json = nlohmann::json::parse(in);
  EXPECT_EQ(json["database"]["rows"], 500);
  EXPECT_EQ(json["database"]["runs"].size(), 2u);
  EXPECT_EQ(json["kind"], "flange-calibration");
  for (const char* key : {"r", "adjusted_r2", "rmse_mm", "mae_mm", "heldout_mae_mm"}) {
    EXPECT_TRUE(json["stats"].contains(key)) << key;
  }
}

TEST(CalibrateCommand, EstimatesOutsideTheCalibratedRangeAreFlagged) {
  const auto dir = fresh_test_dir("calibrate_range");
  const auto db =
      write_file(dir / "db.csv", "t_s,clearance_mm,temp_c,voltage_v\n" + bench_rows(300, 0.0, ""));
  ASSERT_EQ(
      run_flange_captured({"calibrate", "--data", db.string(), "--out", (dir / "m.json").string()})
          .status,
      0);
  const Calibration calibration = load_calibration((dir / "m.json").string());
  EXPECT_FALSE(calibration.estimate(5.0, 50.0).outside_calibration);
  EXPECT_TRUE(calibration.estimate(5.0, 120.0).outside_calibration);
  EXPECT_TRUE(calibration.estimate(9.99, 50.0).outside_calibration);
}

TEST(CalibrateCommand, BadInputExitsTwoAndLeavesTheDatabaseAlone) {
  const auto dir = fresh_test_dir("calibrate_bad");
  const std::string original = "t_s,clearance_mm,temp_c,voltage_v\n" + bench_rows(300, 0.0, "");
  const auto db = write_file(dir / "db.csv", original);
  const auto broken =
      write_file(dir / "broken.csv", "t_s,clearance_mm,temp_c,voltage_v\n0,2,20,1\n1,2,20,12\n");
  FlangeOutcome outcome =
      run_flange_captured({"calibrate", "--data", db.string(), "--append", broken.string(), "--out",
                           (dir / "m.json").string()});
  EXPECT_EQ(outcome.status, 2);
  EXPECT_NE(outcome.err.find("broken.csv:3: column 4 (voltage_v)"), std::string::npos)
      << outcome.err;
  std::ifstream in(db);
  const std::string after((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(after, original);

  const auto flat =
      write_file(dir / "flat.csv", "t_s,clearance_mm,temp_c,voltage_v\n" +
                                       std::string("0,2,25,1\n1,3,25,2\n2,4,25,3\n"
                                                   "3,5,25,4\n4,6,25,5\n5,2,25,1\n"
                                                   "6,3,25,2\n7,4,25,3\n8,5,25,4\n"
                                                   "9,6,25,5\n10,2,25,1\n11,3,25,2\n"
                                                   "12,4,25,3\n13,5,25,4\n14,6,25,5\n"
                                                   "15,2,25,1\n16,3,25,2\n17,4,25,3\n"
                                                   "18,5,25,4\n19,6,25,5\n20,1,25,1\n"));
  outcome = run_flange_captured(
      {"calibrate", "--data", flat.string(), "--out", (dir / "m.json").string()});
  EXPECT_EQ(outcome.status, 2);
  EXPECT_NE(outcome.err.find("temp_c is constant"), std::string::npos) << outcome.err;

  outcome = run_flange_captured(
      {"calibrate", "--data", (dir / "missing.csv").string(), "--out", (dir / "m.json").string()});
  EXPECT_EQ(outcome.status, 2);
  EXPECT_NE(outcome.err.find("missing.csv: cannot open"), std::string::npos) << outcome.err;

  outcome = run_flange_captured(
      {"calibrate", "--data", db.string(), "--out", (dir / "m.json").string(), "--max-order", "9"});
  EXPECT_EQ(outcome.status, 2);
  EXPECT_NE(outcome.err.find("--max-order"), std::string::npos) << outcome.err;
}

TEST(CalibrateCommand, UnwritableOutputFailsBeforeTheDatabaseGrows) {
  const auto dir = fresh_test_dir("calibrate_unwritable");
  const std::string original = "t_s,clearance_mm,temp_c,voltage_v\n" + bench_rows(300, 0.0, "");
  const auto db = write_file(dir / "db.csv", original);
  const auto more = write_file(dir / "more.csv",
                               "t_s,clearance_mm,temp_c,voltage_v\n" + bench_rows(100, 100.0, ""));
  const FlangeOutcome outcome =
      run_flange_captured({"calibrate", "--data", db.string(), "--append", more.string(), "--out",
                           (dir / "no_such_folder" / "m.json").string()});
  EXPECT_EQ(outcome.status, 1);
  EXPECT_EQ(outcome.out, "") << "nothing fitted, nothing printed";
  EXPECT_NE(outcome.err.find("flange calibrate: --out "), std::string::npos) << outcome.err;
  EXPECT_NE(outcome.err.find("cannot write"), std::string::npos) << outcome.err;
  std::ifstream in(db);
  const std::string after((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(after, original);
}

TEST(CalibrateCommand, MalformedModelFileNamesTheField) {
  const auto dir = fresh_test_dir("calibrate_model");
  const auto bad =
      write_file(dir / "bad.json", R"({"kind": "flange-calibration", "order": 9, "scaling": {}})");
  try {
    load_calibration(bad.string());
    FAIL();
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("bad.json: field order is 9; valid range is 1 to 6"),
              std::string::npos)
        << error.what();
  }
}

}  // namespace
}  // namespace flange::cli
