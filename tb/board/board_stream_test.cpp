// SPDX-License-Identifier: MIT
// `flange stream` end to end against the Verilated Basys-3 top attached to a pseudo-terminal
// (pty_board.h): the command opens the pty's slave with the same termios code it uses for
// /dev/ttyUSB1.
// Every filtered word that comes back must equal model::IirCore::step on the word sent.
// Reproduce: build/tb/board_stream_test --gtest_filter='BoardStream.<Name>'
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "board_frame.h"
#include "cli.h"
#include "filter_json.h"
#include "iir_core.h"
#include "pty_board.h"

namespace flange::tb::board {
namespace {

struct Outcome {
  int status;
  std::string out, err;
};

Outcome run(const std::vector<std::string>& args) {
  std::ostringstream out, err;
  const int status = cli::run_flange(args, out, err);
  return {status, out.str(), err.str()};
}

// A short bench recording (simulated, 6 Hz) and its calibration, made once.
class BoardStream : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    // One folder per process: CTest runs the tests of this file in parallel processes.
    dir_ = std::filesystem::path(FLANGE_BINARY_DIR) / "test_files" /
           ("board_stream_" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
    const Outcome sim = run({"simulate", "--scenario", "bench", "--duration", "60", "--seed", "3",
                             "--out", (dir_ / "bench.csv").string()});
    ASSERT_EQ(sim.status, 0) << sim.err;
    const Outcome cal = run({"calibrate", "--data", (dir_ / "bench.csv").string(), "--out",
                             (dir_ / "model.json").string()});
    ASSERT_EQ(cal.status, 0) << cal.err;
  }
  static void TearDownTestSuite() {
    if (!::testing::Test::HasFailure()) std::filesystem::remove_all(dir_);
  }
  // A generous timeout: under a loaded CI machine the simulated board may take a while to answer.
  static std::vector<std::string> args(const Pty& pty, const std::string& out,
                                       const std::string& timeout_ms = "2000") {
    return {"stream",
            "--port",
            pty.slave_name(),
            "--input",
            (dir_ / "bench.csv").string(),
            "--calibration",
            (dir_ / "model.json").string(),
            "--out",
            (dir_ / out).string(),
            "--timeout-ms",
            timeout_ms};
  }
  // Checks every row of a stream output against the model; returns the number of rows.
  static std::size_t expect_matches_model(const std::string& out) {
    model::IirCore core(
        model::load_core_config(FLANGE_SOURCE_DIR "/coeffs/measurement_sos/filter.json"));
    std::ifstream in(dir_ / out);
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line, "t_s,clearance_raw_mm,word_in,word_out,clearance_filt_mm,status");
    std::size_t rows = 0;
    while (std::getline(in, line)) {
      std::istringstream fields(line);
      std::string t, raw, word_in, word_out;
      std::getline(fields, t, ',');
      std::getline(fields, raw, ',');
      std::getline(fields, word_in, ',');
      std::getline(fields, word_out, ',');
      const model::StepResult want = core.step(std::stoi(word_in));
      EXPECT_EQ(std::stoi(word_out), want.sample) << out << " row " << rows;
      ++rows;
    }
    return rows;
  }
  static std::filesystem::path dir_;
};
std::filesystem::path BoardStream::dir_;

TEST_F(BoardStream, RecordingThroughThePtyMatchesTheModel) {
  Pty pty;
  PtyBoard board(pty);
  const Outcome r = run(args(pty, "clean.csv"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("stream: 361 samples"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(" 0 resent"), std::string::npos) << r.out;
  // A pty is no USB-serial port: neither low-latency mode nor an FTDI latency timer can be set,
  // the command says so in one line and streams all the same.
  EXPECT_EQ(r.err, "flange stream: could not set low latency on " + pty.slave_name() +
                       " (TIOCGSERIAL: Inappropriate ioctl for device; no FTDI latency timer in "
                       "sysfs): replies may wait for the chip's timer\n");
  EXPECT_EQ(expect_matches_model("clean.csv"), 361u);
  EXPECT_FALSE(board.assertion_failed());
  // docs/board.md, "Program the board", step 6: `flange run --engine model` on the same input
  // gives the board's clearance_filt_mm row for row.
  const Outcome model_run = run({"run", "--input", (dir_ / "bench.csv").string(), "--calibration",
                                 (dir_ / "model.json").string(), "--coeffs",
                                 FLANGE_SOURCE_DIR "/coeffs/measurement_sos/filter.json",
                                 "--engine", "model", "--out", (dir_ / "model_run.csv").string()});
  ASSERT_EQ(model_run.status, 0) << model_run.err;
  const auto column = [](const std::filesystem::path& path, const std::string& name) {
    std::ifstream in(path);
    std::string line, field;
    std::getline(in, line);
    std::size_t index = 0;
    for (std::istringstream header(line); std::getline(header, field, ','); ++index) {
      if (field == name) break;
    }
    std::vector<std::string> values;
    while (std::getline(in, line)) {
      std::istringstream fields(line);
      for (std::size_t i = 0; i <= index; ++i) std::getline(fields, field, ',');
      values.push_back(field);
    }
    return values;
  };
  const std::vector<std::string> board_mm = column(dir_ / "clean.csv", "clearance_filt_mm");
  const std::vector<std::string> model_mm = column(dir_ / "model_run.csv", "clearance_filt_mm");
  ASSERT_EQ(board_mm.size(), 361u);
  ASSERT_EQ(model_mm.size(), 361u);
  for (std::size_t row = 0; row < board_mm.size(); ++row) {
    ASSERT_EQ(board_mm[row], model_mm[row]) << "row " << row + 1;
  }
}

TEST_F(BoardStream, SecondSessionStartsFromAFreshFilter) {
  // Without the session reset the second run would continue the first run's filter history
  // (and its first SEQ could be taken for a retransmission).
  Pty pty;
  PtyBoard board(pty);
  ASSERT_EQ(run(args(pty, "first.csv")).status, 0);
  const Outcome r = run(args(pty, "second.csv"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(expect_matches_model("second.csv"), 361u);
}

TEST_F(BoardStream, NoisyCableIsRecoveredBitExact) {
  Pty pty;
  // Flip a bit in one request, drop a byte of another: both get no reply, the host resends.
  constexpr std::uint64_t board_request_bytes = host::board::kRequestBytes;
  PtyBoard board(pty, [](std::uint64_t index, std::uint8_t& byte) {
    if (index == board_request_bytes * 40 + 3) byte ^= 0x04;
    return index != board_request_bytes * 100 + 1;
  });
  const Outcome r = run(args(pty, "noisy.csv", "400"));
  ASSERT_EQ(r.status, 0) << r.err;
  // Two requests were damaged; a slow (loaded) simulation may cause more resends, never fewer.
  const std::size_t at = r.out.find(" resent");
  ASSERT_NE(at, std::string::npos) << r.out;
  const std::size_t from = r.out.rfind(' ', at - 1);
  EXPECT_GE(std::stoi(r.out.substr(from + 1, at - from - 1)), 2) << r.out;
  EXPECT_EQ(expect_matches_model("noisy.csv"), 361u);
}

TEST_F(BoardStream, SilentBoardGivesAClearErrorAfterTheTimeout) {
  Pty pty;  // nothing behind it
  std::vector<std::string> a = args(pty, "silent.csv", "200");
  a.insert(a.end(), {"--retries", "1"});
  const auto start = std::chrono::steady_clock::now();
  const Outcome r = run(a);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("does not answer"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(pty.slave_name()), std::string::npos) << r.err;
  EXPECT_GE(s, 0.39);
  EXPECT_LT(s, 5.0);
}

TEST_F(BoardStream, BadRowIsRefusedBeforeTheBoardSeesASample) {
  // Row 200 of a copy of the recording has a voltage above the sensor's 10 V.
  std::ifstream in(dir_ / "bench.csv");
  std::ofstream bad(dir_ / "bad.csv");
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    if (n == 200) line = line.substr(0, line.rfind(',')) + ",12.5";
    bad << line << "\n";
  }
  bad.close();
  Pty pty;
  PtyBoard board(pty);
  std::vector<std::string> a = args(pty, "bad_out.csv");
  a[4] = (dir_ / "bad.csv").string();
  const Outcome r = run(a);
  EXPECT_EQ(r.status, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("bad.csv:200:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("voltage_v"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir_ / "bad_out.csv"))
      << "nothing streamed, nothing written";
}

TEST_F(BoardStream, WithoutACalibrationTheThesisRegressionConverts) {
  Pty pty;
  PtyBoard board(pty);
  std::vector<std::string> a = args(pty, "eq314.csv");
  a.erase(a.begin() + 5, a.begin() + 7);  // --calibration model.json
  const Outcome r = run(a);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(expect_matches_model("eq314.csv"), 361u);
}

TEST_F(BoardStream, MissingPortIsReported) {
  Pty pty;
  std::vector<std::string> a = args(pty, "missing.csv");
  a[2] = "/dev/does-not-exist-flange";
  const Outcome r = run(a);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("cannot open serial port /dev/does-not-exist-flange"), std::string::npos)
      << r.err;
}

}  // namespace
}  // namespace flange::tb::board
