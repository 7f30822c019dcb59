// SPDX-License-Identifier: MIT
// Every subcommand's bad inputs in one table: the exit status, one line on stderr that names what
// is wrong, and no byte of the input echoed raw. Also what is accepted with a note: a
// spreadsheet's byte-order mark and a logger's extra columns.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "cli.h"
#include "flange_in_process.h"
#include "test_files.h"

namespace flange::cli {
namespace {

namespace fs = std::filesystem;
using testing::command_text;
using testing::fresh_test_dir;
using testing::write_file;

struct BadInput {
  std::vector<std::string> args;
  int status;            // the documented exit status
  std::string expected;  // a part of the one line on stderr
};

// Files every case may name, in a folder of the test's own (CTest runs the tests in parallel).
struct InputFiles {
  explicit InputFiles(const std::string& folder) : dir(fresh_test_dir(folder)) {}
  fs::path dir;
  std::string header_only =
      write_file(dir / "header_only.csv", "t_s,clearance_mm,temp_c,voltage_v\n").string();
  std::string binary =
      write_file(dir / "binary.csv", std::string("PK\x03\x04\0\x14\x80\xff garbage", 16)).string();
  std::string good =
      write_file(dir / "good.csv", "t_s,clearance_mm,temp_c,voltage_v\n0,2,20,1\n1,3,20,2\n")
          .string();
  // 40 rows: fewer than 5-fold cross-validation in 64-row blocks needs.
  std::string short_calibration =
      write_file(dir / "short.csv",
                 [] {
                   std::string text = "t_s,clearance_mm,temp_c,voltage_v\n";
                   for (int i = 0; i < 40; ++i) {
                     text += std::to_string(i) + "," + std::to_string(2.0 + 0.2 * i) + "," +
                             std::to_string(20 + (i * 7) % 40) + "," +
                             std::to_string(0.5 + 0.18 * i) + "\n";
                   }
                   return text;
                 }())
          .string();
  std::string filter =
      (fs::path(FLANGE_SOURCE_DIR) / "coeffs/measurement_sos/filter.json").string();
  std::string out(const std::string& name) const { return (dir / name).string(); }
  // Locomotive manifests naming good.csv: each wrong in one way.
  std::string manifest(const std::string& name, const std::string& channels) const {
    return write_file(dir / name, "{\"channels\": [" + channels + "]}").string();
  }
  std::string duplicate_channel = manifest(
      "duplicate.json", R"({"channel": 1, "axle": 1, "side": "left", "file": "good.csv"},)"
                        R"({"channel": 1, "axle": 1, "side": "right", "file": "header_only.csv"})");
  std::string channel_12 = manifest(
      "channel_12.json", R"({"channel": 12, "axle": 1, "side": "left", "file": "good.csv"})");
  std::string missing_channel_file = manifest(
      "missing_file.json", R"({"channel": 0, "axle": 1, "side": "left", "file": "gone.csv"})");
  std::string bad_json = write_file(dir / "bad.json", "{\"channels\": [{\"channel\": 0,").string();
};

// Runs flange; its stderr in `err`.
int flange(const std::vector<std::string>& args, std::string& err) {
  std::ostringstream out, err_stream;
  const int status = run_flange(args, out, err_stream);
  err = err_stream.str();
  return status;
}

// `flange design`: ranges, numbers, channel lists and poles the format cannot hold.
std::vector<BadInput> design_cases() {
  return {
      {{"design", "--fs", "6", "--order", "40", "--fc", "1"}, 2, "--order"},
      {{"design", "--fs", "abc", "--order", "4", "--fc", "1"}, 2, "--fs: 'abc' is not a valid"},
      {{"design", "--fs", "100", "--order", "4", "--fc", "1", "--channels", "33"},
       2,
       "--channels: 33 is outside 1 to 32"},
      {{"design", "--fs", "100", "--order", "4", "--fc", "1", "--channel-fc", "1,2"},
       2,
       "leave out --fc"},
      {{"design", "--fs", "100", "--order", "4", "--channels", "3", "--channel-fc", "1,2"},
       2,
       "--channels 3 but --channel-fc names 2"},
      {{"design", "--fs", "100", "--order", "4", "--channel-fc", "1,60"}, 2, "--fc 60"},
      {{"design", "--fs", "6", "--order", "5", "--structure", "df1", "--channel-fc", "0.01,2.9"},
       3,
       "channel 0 (fc = 0.01 Hz): direct form (order 5) with 18-bit coefficients puts 1 pole"},
  };
}

// `flange cosim` and `flange synth`: a coefficient set missing or not JSON.
std::vector<BadInput> coefficient_set_cases(const InputFiles& f) {
  return {
      {{"cosim", "--coeffs", f.out("missing.json")}, 2, "missing.json"},
      {{"cosim", "--coeffs", f.binary}, 2, "binary.csv"},
      {{"synth", "--coeffs", f.out("no_set")}, 2, "is missing"},
  };
}

// `flange simulate`: a bad rate, an unknown effect, too many wheels.
std::vector<BadInput> simulate_cases(const InputFiles& f) {
  return {
      {{"simulate", "--scenario", "bench", "--seed", "1", "--fs", "-1", "--out", f.out("s.csv")},
       2,
       "--fs"},
      {{"simulate", "--scenario", "bench", "--seed", "1", "--effect", "bogus", "--out",
        f.out("s.csv")},
       2,
       "bogus"},
      {{"simulate", "--scenario", "loco", "--seed", "1", "--wheels", "13", "--out", f.out("l")},
       2,
       "--wheels: 13 is outside its valid range: a whole number 1 to 12"},
  };
}

// `flange calibrate`: a database without rows, not text, or too short.
std::vector<BadInput> calibrate_cases(const InputFiles& f) {
  return {
      {{"calibrate", "--data", f.header_only, "--out", f.out("m.json")}, 2, ":2: no data rows"},
      {{"calibrate", "--data", f.binary, "--out", f.out("m.json")}, 2, "not a text file"},
      {{"calibrate", "--data", f.short_calibration, "--out", f.out("m.json")},
       2,
       "40 points with a clearance reference; at least 257 are needed"},
  };
}

// `flange run`: the recording, the calibration and a locomotive's manifest, each wrong in one way,
// and options that exclude each other.
std::vector<BadInput> run_cases(const InputFiles& f) {
  return {
      {{"run", "--input", f.header_only, "--calibration", f.binary, "--coeffs", f.filter},
       2,
       "binary.csv"},
      {{"run", "--input", f.binary, "--calibration", f.out("none.json"), "--coeffs", f.filter},
       2,
       "none.json: cannot open the calibration"},
      {{"run", "--manifest", f.out("none.json"), "--calibration", f.out("none.json"), "--coeffs",
        f.filter},
       2,
       "none.json: cannot open the manifest"},
      {{"run", "--manifest", f.duplicate_channel, "--calibration", f.out("none.json"), "--coeffs",
        f.filter},
       2,
       "duplicate.json: field channels[1].channel: 1 is already channels[0]'s"},
      {{"run", "--manifest", f.channel_12, "--calibration", f.out("none.json"), "--coeffs",
        f.filter},
       2,
       "channel_12.json: field channels[0].channel: 12 is outside its valid range: a whole number "
       "0 to 11"},
      {{"run", "--manifest", f.missing_channel_file, "--calibration", f.out("none.json"),
        "--coeffs", f.filter},
       2,
       "missing_file.json: field channels[0].file: "},
      {{"run", "--manifest", f.bad_json, "--calibration", f.out("none.json"), "--coeffs", f.filter},
       2,
       "bad.json: not valid JSON"},
      {{"run", "--manifest", f.channel_12, "--input", f.good, "--calibration", f.out("none.json"),
        "--coeffs", f.filter},
       2,
       "--input excludes --manifest"},
      {{"run", "--manifest", f.channel_12, "--report", f.out("r"), "--calibration",
        f.out("none.json"), "--coeffs", f.filter},
       2,
       "--report: with --manifest the report goes into the --out folder"},
      {{"run", "--input", f.good, "--calibration", f.out("none.json"), "--coeffs", f.filter,
        "--out", f.good},
       2,
       "good.csv: the output CSV is the file given to --input; choose another --out"},
      {{"run", "--calibration", f.out("none.json"), "--coeffs", f.filter},
       2,
       "--input REC.csv or --manifest locomotive.json is required"},
  };
}

// `flange stream`: the recording or manifest to replay, the baud rate and the window.
std::vector<BadInput> stream_cases(const InputFiles& f) {
  return {
      {{"stream", "--port", "/dev/null", "--input", f.header_only, "--out", f.out("b.csv")},
       2,
       ":2: no data rows"},
      {{"stream", "--port", "/dev/null", "--input", f.header_only, "--out", f.out("b.csv"),
        "--baud", "12000000"},
       2,
       "--baud"},
      {{"stream", "--port", "/dev/null", "--manifest", f.out("missing.json"), "--out", f.out("s")},
       2,
       "missing.json"},
      {{"stream", "--port", "/dev/null", "--input", f.header_only, "--manifest",
        f.out("missing.json"), "--out", f.out("s")},
       2,
       "--input excludes --manifest"},
      {{"stream", "--port", "/dev/null", "--out", f.out("s")}, 2, "give --input"},
      {{"stream", "--port", "/dev/null", "--input", f.header_only, "--out", f.out("b.csv"),
        "--window", "33"},
       2,
       "--window"},
      {{"stream", "--port", "/dev/null", "--input", f.header_only, "--out", f.out("b.csv"),
        "--window", "0"},
       2,
       "--window"},
  };
}

// `flange diagnose` (a recording, the session clocks, the self-test's options) and `flange demo`.
std::vector<BadInput> diagnose_and_demo_cases(const InputFiles& f) {
  return {
      {{"diagnose", "--real", f.header_only, "--holdout-fraction", "0.3", "--out", f.out("d")},
       2,
       ":2: no data rows"},
      {{"diagnose", "--real", f.binary, "--holdout-fraction", "0.3", "--out", f.out("d")},
       2,
       "not a text file"},
      {{"diagnose", "--hw", "--coeffs", f.out("missing.json")}, 2, "missing.json"},
      {{"diagnose", "--real", f.good, "--holdout", f.good, "--real-start", "2026-13-01T00:00:00Z",
        "--holdout-start", "2026-11-21T09:30:00Z", "--out", f.out("d")},
       2,
       "--real-start: '2026-13-01T00:00:00Z' is not a UTC time YYYY-MM-DDThh:mm:ss[.fff]Z"},
      {{"diagnose", "--real", f.good, "--holdout", f.good, "--holdout-start",
        "2026-11-21T09:30:00Z", "--out", f.out("d")},
       2,
       "--holdout-start requires --real-start"},
      {{"diagnose", "--real", f.good, "--holdout-fraction", "0.3", "--real-start",
        "2026-11-21T09:30:00Z", "--out", f.out("d")},
       2,
       "--real-start requires --holdout"},
      {{"diagnose", "--selftest", "--cases", "0"}, 2, "--cases"},
      {{"diagnose", "--selftest", "--reality", "moon"}, 2, "--reality: moon not in {twin,alt,third}"},
      {{"diagnose", "--selftest", "--reality", "alt", "--pairs", "0"}, 2, "not in range 1 to 1000"},
      {{"demo", "--out", f.good + "/inside_a_file"}, 1, "cannot create directories"},
  };
}

// The case's exit status, and one line on stderr of printable ASCII that names what is wrong.
void expect_one_clean_line(const BadInput& c) {
  std::string err;
  const int status = flange(c.args, err);
  const std::string reproduce = command_text(c.args);
  EXPECT_EQ(status, c.status) << reproduce << "\n" << err;
  EXPECT_NE(err.find(c.expected), std::string::npos) << reproduce << "\n" << err;
  ASSERT_FALSE(err.empty()) << reproduce;
  EXPECT_EQ(err.find('\n'), err.size() - 1) << reproduce << ": more than one line\n" << err;
  for (const char ch : err) {
    const auto byte = static_cast<unsigned char>(ch);
    EXPECT_TRUE(ch == '\n' || (byte >= 0x20 && byte < 0x7f))
        << reproduce << ": raw byte " << static_cast<int>(byte) << " in\n"
        << err;
  }
}

TEST(BadInput, EverySubcommandAnswersInOneLineWithItsExitStatus) {
  const InputFiles f("bad_input_table");
  for (const std::vector<BadInput>& cases :
       {design_cases(), coefficient_set_cases(f), simulate_cases(f), calibrate_cases(f),
        run_cases(f), stream_cases(f), diagnose_and_demo_cases(f)}) {
    for (const BadInput& c : cases) ASSERT_NO_FATAL_FAILURE(expect_one_clean_line(c));
  }
}

TEST(BadInput, ASpreadsheetsByteOrderMarkAndExtraColumnsAreAcceptedWithANote) {
  const InputFiles f("bad_input_spreadsheet");
  std::string rows;
  for (int i = 0; i < 300; ++i) {
    const double d = 2.0 + 0.02 * i;
    rows += std::to_string(i) + "," + std::to_string(d) + "," + std::to_string(20 + (i * 7) % 40) +
            "," + std::to_string(0.5 + 0.9 * (d - 1.5) - 0.002 * ((i * 7) % 40)) + ",55\n";
  }
  const std::string csv =
      write_file(f.dir / "excel.csv",
                 "\xEF\xBB\xBFt_s,clearance_mm,temp_c,voltage_v,humidity\n" + rows)
          .string();
  std::string err;
  EXPECT_EQ(flange({"calibrate", "--data", csv, "--out", f.out("m.json"), "--max-order", "1"}, err),
            0)
      << err;
  EXPECT_NE(err.find("note: " + csv + ":1: ignoring column(s) 'humidity'"), std::string::npos)
      << err;
}

}  // namespace
}  // namespace flange::cli
