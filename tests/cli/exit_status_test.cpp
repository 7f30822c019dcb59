// SPDX-License-Identifier: MIT
// The exit-status table (cli/exit_status.h, cli/README.md "Exit status"): each row, and for every
// subcommand one case per non-zero status it documents, run as users run it: the status, and one
// line on stderr that starts with the subcommand's name.
#include "exit_status.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include "design_error.h"
#include "filter_json.h"
#include "flange_in_process.h"
#include "input_error.h"
#include "sim_error.h"
#include "store.h"
#include "test_files.h"
#include "vivado_report.h"

namespace flange::cli {
namespace {

namespace fs = std::filesystem;
using testing::FlangeOutcome;
using testing::fresh_test_dir;
using testing::command_text;
using testing::run_flange_captured;
using testing::write_file;

TEST(ExitStatusTable, EachRowGivesItsStatus) {
  EXPECT_EQ(exit_status_of(coeffs::DesignRejected("x")), kExitDefect);
  EXPECT_EQ(exit_status_of(host::InputError("x")), kExitBadArgument);
  EXPECT_EQ(exit_status_of(coeffs::BadArgument("x")), kExitBadArgument);
  EXPECT_EQ(exit_status_of(sim::BadArgument("x")), kExitBadArgument);
  EXPECT_EQ(exit_status_of(model::FilterJsonError("x")), kExitBadArgument);
  EXPECT_EQ(exit_status_of(tb::VivadoReportError("x")), kExitBadArgument);
  EXPECT_EQ(exit_status_of(host::StoreUrlError("x")), kExitBadArgument);
  EXPECT_EQ(exit_status_of(std::invalid_argument("x")), kExitBadArgument);
  EXPECT_EQ(exit_status_of(host::StoreError("x")), kExitFailure);
  EXPECT_EQ(exit_status_of(tb::VivadoReportMissing("x")), kExitFailure);
  EXPECT_EQ(exit_status_of(std::runtime_error("x")), kExitFailure);
  EXPECT_EQ(exit_status_of(std::out_of_range("x")), kExitFailure);
}

TEST(ExitStatusTable, AnOptionNamedBeforeTheMessageKeepsTheStatus) {
  try {
    naming_option("--store", [] { throw host::StoreUrlError("store x: no scheme"); });
    FAIL() << "naming_option swallowed the exception";
  } catch (const OptionError& error) {
    EXPECT_STREQ(error.what(), "--store: store x: no scheme");
    EXPECT_EQ(exit_status_of(error), kExitBadArgument);
  }
  try {
    naming_option("--truth", [] { throw std::runtime_error("t.json: cannot write"); });
    FAIL() << "naming_option swallowed the exception";
  } catch (const OptionError& error) {
    EXPECT_EQ(exit_status_of(error), kExitFailure);
  }
  EXPECT_NO_THROW(naming_option("--store", [] {}));
}

// Inputs every case may name, in a folder of this process's own (CTest runs the tests of this
// file as processes side by side).
class ExitStatus : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = fresh_test_dir("exit_status_" + std::to_string(::getpid()));
    write_file(dir_ / "header_only.csv", "t_s,clearance_mm,temp_c,voltage_v\n");
    write_file(dir_ / "a_file", "not a folder\n");
    std::string rows = "t_s,clearance_mm,temp_c,voltage_v\n";
    for (int i = 0; i < 300; ++i) {
      const double d = 2.0 + 0.02 * i;
      rows += std::to_string(i) + "," + std::to_string(d) + "," +
              std::to_string(20 + (i * 7) % 40) + "," +
              std::to_string(0.5 + 0.9 * (d - 1.5) - 0.002 * ((i * 7) % 40)) + "\n";
    }
    write_file(dir_ / "session.csv", rows);
  }
  static std::string path(const std::string& name) { return (dir_ / name).string(); }
  // A path under a plain file: nothing can be written there.
  static std::string unwritable(const std::string& name) { return path("a_file/" + name); }
  static std::string source(const std::string& name) {
    return (fs::path(FLANGE_SOURCE_DIR) / name).string();
  }

  // `args` ends with `status` and one line on stderr that starts with `prefix` ("flange design:")
  // and holds `names`.
  static void expect_exit(const std::vector<std::string>& args, int status,
                          const std::string& prefix, const std::string& names = "") {
    const FlangeOutcome outcome = run_flange_captured(args);
    const std::string reproduce = command_text(args);
    EXPECT_EQ(outcome.status, status) << reproduce << "\n" << outcome.err;
    EXPECT_EQ(outcome.err.rfind(prefix, 0), 0u) << reproduce << "\n" << outcome.err;
    EXPECT_NE(outcome.err.find(names), std::string::npos) << reproduce << "\n" << outcome.err;
    ASSERT_FALSE(outcome.err.empty()) << reproduce;
    EXPECT_EQ(outcome.err.find('\n'), outcome.err.size() - 1)
        << reproduce << ": more than one line\n"
        << outcome.err;
  }

  static fs::path dir_;
};

fs::path ExitStatus::dir_;

TEST_F(ExitStatus, Design) {
  expect_exit({"design", "--fs", "6", "--order", "40", "--fc", "1"}, 2,
              "flange design: ", "--order");
  expect_exit({"design", "--fs", "100", "--order", "7", "--fc", "0.259", "--structure", "df1"}, 3,
              "flange design: ", "use --structure sos or more coefficient bits");
  expect_exit(
      {"design", "--fs", "6", "--order", "4", "--fc", "1", "--no-plot", "--out", unwritable("set")},
      1, "flange design: ", "a_file");
}

TEST_F(ExitStatus, Cosim) {
  expect_exit({"cosim", "--coeffs", path("missing.json")}, 2, "flange cosim: ", "missing.json");
  // A set without its package and ROM image beside it is refused before anything is built.
  fs::create_directories(dir_ / "lone_set");
  fs::copy_file(source("coeffs/measurement_sos/filter.json"), dir_ / "lone_set/filter.json",
                fs::copy_options::overwrite_existing);
  expect_exit({"cosim", "--coeffs", path("lone_set/filter.json")}, 2,
              "flange cosim: ", "iir_coeffs_pkg.sv: missing");
  // Without a data folder no runner can be built (status 1, before Verilator runs).
  const char* before = std::getenv("FLANGE_DATA_DIR");
  const std::string saved = before ? before : "";
  ::setenv("FLANGE_DATA_DIR", path("no_data_folder").c_str(), 1);
  expect_exit({"cosim", "--coeffs", source("coeffs/measurement_sos/filter.json")}, 1,
              "flange cosim: ", "FLANGE_DATA_DIR=");
  if (before) {
    ::setenv("FLANGE_DATA_DIR", saved.c_str(), 1);
  } else {
    ::unsetenv("FLANGE_DATA_DIR");
  }
}

TEST_F(ExitStatus, Synth) {
  expect_exit({"synth", "--coeffs", path("no_set")}, 2, "flange synth: ", "is missing");
  expect_exit({"synth", "--coeffs", source("coeffs/measurement_sos"), "--vivado-report",
               path("no_reports"), "--out", path("synth.md")},
              1, "flange synth: ", "cannot be read");
}

TEST_F(ExitStatus, Simulate) {
  expect_exit(
      {"simulate", "--scenario", "bench", "--seed", "1", "--fs", "-1", "--out", path("s.csv")}, 2,
      "flange simulate: ", "--fs");
  expect_exit({"simulate", "--scenario", "fleet", "--locomotives", "1", "--days", "3", "--store",
               "mysql://x"},
              2, "flange simulate: --store: store mysql://x");
  expect_exit({"simulate", "--scenario", "fleet-alt", "--wheels", "3", "--out", path("alt")}, 2,
              "flange simulate: ", "--wheels");
  expect_exit({"simulate", "--scenario", "bench", "--seed", "1", "--duration", "600", "--out",
               unwritable("s.csv")},
              1, "flange simulate: ", "cannot write the recording");
}

TEST_F(ExitStatus, CalibrateRunAndMaintenance) {
  expect_exit({"calibrate", "--data", path("header_only.csv"), "--out", path("m.json")}, 2,
              "flange calibrate: ", ":2: no data rows");
  expect_exit({"calibrate", "--data", path("session.csv"), "--out", unwritable("m.json")}, 1,
              "flange calibrate: --out ", "cannot write");
  const std::vector<std::string> calibrate{
      "calibrate", "--data", path("session.csv"), "--out", path("m.json"), "--max-order", "1"};
  ASSERT_EQ(run_flange_captured(calibrate).status, 0) << command_text(calibrate);

  const std::string filter = source("coeffs/measurement_sos/filter.json");
  expect_exit({"run", "--calibration", path("m.json"), "--coeffs", filter}, 2,
              "flange run: ", "--input REC.csv or --manifest locomotive.json is required");
  expect_exit(
      {"run", "--input", path("session.csv"), "--calibration", path("m.json"), "--coeffs", filter,
       "--store", "sqlite:" + path("no_such_folder/fleet.db"), "--out", path("never.csv")},
      1, "flange run: store ");

  expect_exit({"maintenance", "--store", "sqlite:" + path("depot.db"), "--locomotive", "A01",
               "--kind", "reprofile", "--at", "2027-03-05T12:00:00Z"},
              2, "flange maintenance: ", "--axle");
  expect_exit(
      {"maintenance", "--store", "sqlite:" + path("no_such_folder/depot.db"), "--locomotive", "A01",
       "--kind", "reprofile", "--axle", "1", "--at", "2027-03-05T12:00:00Z"},
      1, "flange maintenance: store ");
}

TEST_F(ExitStatus, Stream) {
  expect_exit(
      {"stream", "--port", "/dev/null", "--input", path("header_only.csv"), "--out", path("b.csv")},
      2, "flange stream: ", ":2: no data rows");
  expect_exit({"stream", "--port", path("no_such_port"), "--input", path("session.csv"), "--out",
               path("b.csv")},
              1, "flange stream: ", "no_such_port");
}

TEST_F(ExitStatus, Wear) {
  expect_exit(
      {"wear", "--store", "sqlite:" + path("fleet.db"), "--out", path("w"), "--warning-mm", "-3"},
      2, "flange wear: ", "warning");
  expect_exit({"wear", "--store", "mysql://x", "--out", path("w")}, 2,
              "flange wear: --store: store mysql://x");
  expect_exit({"wear", "--store", "sqlite:" + path("missing.db"), "--out", path("w")}, 1,
              "flange wear: store ", "no such file");
}

TEST_F(ExitStatus, DiagnoseData) {
  expect_exit({"diagnose", "--real", path("header_only.csv"), "--holdout-fraction", "0.3", "--out",
               path("d")},
              2, "flange diagnose: ", ":2: no data rows");
  const std::vector<std::string> simulate{"simulate", "--scenario", "bench",
                                          "--seed",   "1",          "--duration",
                                          "600",      "--out",      path("bench.csv")};
  ASSERT_EQ(run_flange_captured(simulate).status, 0) << command_text(simulate);
  expect_exit({"diagnose", "--real", path("bench.csv"), "--holdout-fraction", "0.3", "--out",
               unwritable("d")},
              1, "flange diagnose: ", "a_file");
}

TEST_F(ExitStatus, DiagnoseSelftests) {
  // The self-tests' arguments are checked as they are parsed: the parser names the subcommand.
  expect_exit({"diagnose", "--selftest", "--cases", "0"}, 2, "flange diagnose: ", "--cases");
  expect_exit({"diagnose", "--selftest", "--cases", "1", "--duration", "600", "--jobs", "1",
               "--out", unwritable("selftest")},
              1, "flange diagnose --selftest: ", "a_file");
  expect_exit({"diagnose", "--selftest", "--reality", "alt", "--pairs", "0"}, 2,
              "flange diagnose: ", "not in range 1 to 1000");
  expect_exit({"diagnose", "--selftest", "--reality", "alt", "--pairs", "1", "--duration", "600",
               "--jobs", "1", "--out", unwritable("alt_selftest")},
              1, "flange diagnose --selftest --reality alt: ", "a_file");
}

TEST_F(ExitStatus, DiagnoseHardware) {
  expect_exit({"diagnose", "--hw", "--coeffs", path("missing.json")}, 2,
              "flange diagnose --hw: ", "missing.json");
  expect_exit({"diagnose", "--hw", "--thesis-eq-4-20", "--coeffs",
               source("coeffs/vehicle_sos/filter.json"), "--out", unwritable("hw")},
              1, "flange diagnose --hw: ", "a_file");
}

TEST_F(ExitStatus, Demo) {
  expect_exit({"demo", "--out", unwritable("demo")}, 1,
              "flange demo: ", "cannot create directories");
  expect_exit({"demo", "--bogus"}, 2, "flange demo: ", "--bogus");
}

}  // namespace
}  // namespace flange::cli
