// SPDX-License-Identifier: MIT
// `flange run` as a user runs it: simulate, calibrate, run through each engine; the output CSV,
// the summary, the report; bad input with and without --lenient.
#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>
#include <map>
#include <sstream>

#include "cli.h"
#include "flange_in_process.h"
#include "test_files.h"

namespace flange::cli {
namespace {

using testing::FlangeOutcome;
using testing::run_flange_captured;

using testing::fresh_test_dir;
using testing::write_file;

std::string read(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

const std::string kMeasurement =
    std::string(FLANGE_SOURCE_DIR) + "/coeffs/measurement_sos/filter.json";

// A 20-minute simulated bench session and its calibration, made once for all tests.
class RunCommand : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    // One folder per process: CTest runs the tests of this file in parallel processes.
    dir_ = fresh_test_dir("run_command_" + std::to_string(::getpid()));
    const FlangeOutcome sim =
        run_flange_captured({"simulate", "--scenario", "bench", "--duration", "1200", "--seed", "5",
                             "--out", (dir_ / "bench.csv").string()});
    ASSERT_EQ(sim.status, 0) << sim.err;
    const FlangeOutcome cal =
        run_flange_captured({"calibrate", "--data", (dir_ / "bench.csv").string(), "--out",
                             (dir_ / "model.json").string()});
    ASSERT_EQ(cal.status, 0) << cal.err;
  }
  static void TearDownTestSuite() {
    if (!::testing::Test::HasFailure()) std::filesystem::remove_all(dir_);
  }
  static std::vector<std::string> run_args(const std::string& input, const std::string& engine) {
    return {"run",      "--input",    input,      "--calibration", (dir_ / "model.json").string(),
            "--coeffs", kMeasurement, "--engine", engine};
  }
  static std::filesystem::path dir_;
};
std::filesystem::path RunCommand::dir_;

TEST_F(RunCommand, FilteringHalvesTheErrorAndWritesEveryRow) {
  std::vector<std::string> args = run_args((dir_ / "bench.csv").string(), "model");
  args.insert(args.end(),
              {"--out", (dir_ / "out_model.csv").string(), "--report", (dir_ / "report").string()});
  const FlangeOutcome outcome = run_flange_captured(args);
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  EXPECT_NE(outcome.out.find("rows read 7201, flagged 0"), std::string::npos) << outcome.out;
  const std::string csv = read(dir_ / "out_model.csv");
  EXPECT_EQ(csv.rfind("t_s,clearance_raw_mm,clearance_filt_mm,flange_mm,alarm,flags\n", 0), 0u);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 7202);
  // MAE before and after, from the summary line.
  const auto mae = [&](const char* label) {
    const std::size_t at = outcome.out.find(label);
    EXPECT_NE(at, std::string::npos) << label;
    return std::stod(outcome.out.substr(outcome.out.find("MAE ", at) + 4));
  };
  const double before = mae("error before filtering");
  const double after = mae("error after filtering");
  EXPECT_LT(after, 0.6 * before) << outcome.out;
  for (const char* file :
       {"index.html", "traces.svg", "error_by_region.svg", "response.svg", "spectra.svg"}) {
    EXPECT_TRUE(std::filesystem::exists(dir_ / "report" / file)) << file;
  }
}

TEST_F(RunCommand, FloatEngineStaysWithinRoundingOfTheModel) {
  std::vector<std::string> model_args = run_args((dir_ / "bench.csv").string(), "model");
  model_args.insert(model_args.end(), {"--out", (dir_ / "m.csv").string()});
  std::vector<std::string> float_args = run_args((dir_ / "bench.csv").string(), "float");
  float_args.insert(float_args.end(), {"--out", (dir_ / "f.csv").string()});
  ASSERT_EQ(run_flange_captured(model_args).status, 0);
  ASSERT_EQ(run_flange_captured(float_args).status, 0);
  std::istringstream m(read(dir_ / "m.csv")), f(read(dir_ / "f.csv"));
  std::string lm, lf;
  std::getline(m, lm);
  std::getline(f, lf);
  double worst = 0.0;
  while (std::getline(m, lm) && std::getline(f, lf)) {
    auto filt = [](const std::string& line) {
      std::istringstream fields(line);
      std::string value;
      for (int k = 0; k < 3; ++k) std::getline(fields, value, ',');
      return std::stod(value);
    };
    worst = std::max(worst, std::abs(filt(lm) - filt(lf)));
  }
  // A few LSB of 0.24 um each: the fixed-point core is not the error budget.
  EXPECT_LT(worst, 0.005);
}

TEST_F(RunCommand, RtlEngineEqualsTheModelWordForWord) {
  std::vector<std::string> rtl = run_args((dir_ / "bench.csv").string(), "rtl");
  rtl.insert(rtl.end(), {"--out", (dir_ / "r.csv").string()});
  std::vector<std::string> model = run_args((dir_ / "bench.csv").string(), "model");
  model.insert(model.end(), {"--out", (dir_ / "m2.csv").string()});
  const FlangeOutcome outcome = run_flange_captured(rtl);
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  EXPECT_NE(outcome.out.find("0 mismatches"), std::string::npos) << outcome.out;
  ASSERT_EQ(run_flange_captured(model).status, 0);
  EXPECT_EQ(read(dir_ / "r.csv"), read(dir_ / "m2.csv"));
}

TEST_F(RunCommand, BadRowsStopAStrictRunAndAreCountedInALenientOne) {
  std::string text = read(dir_ / "bench.csv");
  // Corrupt line 101 (a voltage out of range) and line 201 (not a number).
  std::istringstream lines(text);
  std::string line, corrupted;
  for (int n = 1; std::getline(lines, line); ++n) {
    if (n == 101) line = line.substr(0, line.rfind(',')) + ",12.5";
    if (n == 201) line = line.substr(0, line.rfind(',')) + ",abc";
    corrupted += line + "\n";
  }
  const auto bad = write_file(dir_ / "bad.csv", corrupted);
  FlangeOutcome strict = run_flange_captured(run_args(bad.string(), "model"));
  EXPECT_EQ(strict.status, 2);
  EXPECT_NE(strict.err.find("bad.csv:101: column 4 (voltage_v): 12.5 is outside"),
            std::string::npos)
      << strict.err;
  std::vector<std::string> lenient = run_args(bad.string(), "model");
  lenient.insert(lenient.end(), {"--lenient", "--out", (dir_ / "lenient.csv").string()});
  const FlangeOutcome outcome = run_flange_captured(lenient);
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  EXPECT_NE(outcome.out.find("rows read 7201, flagged 2 (bad 2"), std::string::npos) << outcome.out;
  const std::string csv = read(dir_ / "lenient.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 7202);  // every row accounted for
  EXPECT_NE(csv.find(",bad_row\n"), std::string::npos);
}

TEST_F(RunCommand, ABadRowPastTheFirstBlockStopsTheRunAtItsLine) {
  // Past the first block of 4096 rows (the pipeline's unit of work) the error is still the one
  // line naming the file, the line and the column.
  std::istringstream lines(read(dir_ / "bench.csv"));
  std::string line, corrupted;
  for (int n = 1; std::getline(lines, line); ++n) {
    if (n == 6001) line = line.substr(0, line.rfind(',')) + ",abc";
    corrupted += line + "\n";
  }
  const auto bad = write_file(dir_ / "bad_late.csv", corrupted);
  std::vector<std::string> args = run_args(bad.string(), "model");
  args.insert(args.end(), {"--out", (dir_ / "bad_late_out.csv").string()});
  const FlangeOutcome strict = run_flange_captured(args);
  EXPECT_EQ(strict.status, 2);
  EXPECT_NE(
      strict.err.find("bad_late.csv:6001: column 4 (voltage_v): 'abc' is not a finite number"),
      std::string::npos)
      << strict.err;
  EXPECT_EQ(std::count(strict.err.begin(), strict.err.end(), '\n'), 1) << strict.err;
}

TEST_F(RunCommand, WithTwoThreadsTheFirstBadLineIsReportedAndTheOutputIsTheSame) {
  // The recording is read ahead in batches of 256 KiB (about 6,000 rows here) on a second thread:
  // a bad line in the second batch is reported with its own line, and when an earlier line is bad
  // too, only by its time order (found in file order, after the second thread has seen the later
  // one), the earlier wins. The output as far as the run got is the same on one thread (the
  // thread writing the output behind the filter writes every row queued before the error).
  std::string text = read(dir_ / "bench.csv");
  const auto corrupt = [&text](const std::map<int, std::string>& changes) {
    std::istringstream lines(text);
    std::string line, corrupted;
    for (int n = 1; std::getline(lines, line); ++n) {
      if (const auto change = changes.find(n); change != changes.end()) {
        line = change->second == "t=0" ? "0" + line.substr(line.find(','))
                                       : line.substr(0, line.rfind(',')) + "," + change->second;
      }
      corrupted += line + "\n";
    }
    return corrupted;
  };
  const auto late = write_file(dir_ / "late_two.csv", corrupt({{7001, "abc"}, {7101, "12.5"}}));
  const auto both = write_file(dir_ / "time_first.csv", corrupt({{3001, "t=0"}, {7001, "abc"}}));
  const std::pair<std::filesystem::path, std::string> cases[] = {
      {late, "late_two.csv:7001: column 4 (voltage_v): 'abc' is not a finite number"},
      {both, "time_first.csv:3001: column 1 (t_s): 0 is not after the previous time"}};
  for (const auto& [input, expected] : cases) {
    std::string one_thread_csv;
    for (const char* threads : {"2", "1"}) {
      std::vector<std::string> args = run_args(input.string(), "model");
      args.insert(args.end(), {"--threads", threads, "--out", (dir_ / "partial.csv").string()});
      const FlangeOutcome outcome = run_flange_captured(args);
      EXPECT_EQ(outcome.status, 2) << threads;
      EXPECT_NE(outcome.err.find(expected), std::string::npos) << threads << ": " << outcome.err;
      EXPECT_EQ(std::count(outcome.err.begin(), outcome.err.end(), '\n'), 1) << outcome.err;
      if (one_thread_csv.empty()) {
        one_thread_csv = read(dir_ / "partial.csv");
      } else {
        EXPECT_EQ(read(dir_ / "partial.csv"), one_thread_csv) << input;
      }
    }
  }
  // And a good recording gives the same output on one thread and two.
  std::string outputs[2];
  for (const int threads : {1, 2}) {
    std::vector<std::string> args = run_args((dir_ / "bench.csv").string(), "model");
    args.insert(args.end(), {"--threads", std::to_string(threads), "--out",
                             (dir_ / "threads.csv").string()});
    const FlangeOutcome outcome = run_flange_captured(args);
    ASSERT_EQ(outcome.status, 0) << outcome.err;
    outputs[threads - 1] = outcome.out + read(dir_ / "threads.csv");
  }
  EXPECT_EQ(outputs[0], outputs[1]);
}

TEST_F(RunCommand, ARecordingAtTheWrongRateIsRefused) {
  const FlangeOutcome sim =
      run_flange_captured({"simulate", "--scenario", "bench", "--fs", "100", "--duration", "5",
                           "--seed", "1", "--out", (dir_ / "fast.csv").string()});
  ASSERT_EQ(sim.status, 0) << sim.err;
  const FlangeOutcome outcome =
      run_flange_captured(run_args((dir_ / "fast.csv").string(), "model"));
  EXPECT_EQ(outcome.status, 2);
  EXPECT_NE(outcome.err.find("does not match the filter's fs = 6 Hz"), std::string::npos)
      << outcome.err;
}

TEST_F(RunCommand, UnknownEngineAndMissingFilesExitTwo) {
  EXPECT_EQ(run_flange_captured(run_args((dir_ / "bench.csv").string(), "vhdl")).status, 2);
  std::vector<std::string> args = run_args((dir_ / "missing.csv").string(), "model");
  const FlangeOutcome outcome = run_flange_captured(args);
  EXPECT_EQ(outcome.status, 2);
  EXPECT_NE(outcome.err.find("missing.csv: cannot open"), std::string::npos) << outcome.err;
}

}  // namespace
}  // namespace flange::cli
