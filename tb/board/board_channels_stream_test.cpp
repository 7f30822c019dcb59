// SPDX-License-Identifier: MIT
// The multichannel stream library (host/board_link/channel_stream.h, stream_session.h) against the
// Verilated 12-channel board top behind a pseudo-terminal (pty_board.h): channels
// interleaved on the one link, every reply checked against model::IirSampleBank by the library and
// against model::IirCore here; a noisy cable; recordings on chosen channels with their output CSVs;
// channels the board or the coefficient set lacks refused with one line. (A pty has no baud rate:
// the host sets 921600 as for a real board, the simulated board runs at its ClksPerBit.)
// Reproduce: build/tb/board_channels_stream_test --gtest_filter='BoardChannelsStream.<Name>'
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <numeric>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "board_link.h"
#include "channel_stream.h"
#include "cli.h"
#include "filter_json.h"
#include "iir_core.h"
#include "input_error.h"
#include "pty_board.h"
#include "serial_port.h"
#include "stream_session.h"

namespace flange::tb::board {
namespace {

constexpr int kBaud = 921600;
constexpr int kChannels = 12;

// `channels` channels of noisy words, channel c at its own level and with 90 + 3c of them (the
// shorter ones drop out of the interleaving first). The filter is slow (its first non-zero output
// comes about 50 samples after a step), so each channel has some 30 or more non-zero outputs.
std::vector<host::ChannelWords> channel_words(int channels, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> noise(-1000, 1000);
  std::vector<host::ChannelWords> out;
  for (int c = 0; c < channels; ++c) {
    host::ChannelWords ch{c, {}};
    const int level = (c % 2 ? 1 : -1) * (6000 + 2000 * c);
    for (int n = 0; n < 90 + 3 * c; ++n) {
      ch.words.push_back(static_cast<std::int16_t>(level + noise(rng)));
    }
    out.push_back(std::move(ch));
  }
  return out;
}

// Every channel's replies equal the cycle model's outputs for that channel's words.
void expect_model_outputs(const std::vector<host::ChannelWords>& in,
                          const std::vector<host::ChannelReplies>& out) {
  model::IirCore core(model::load_core_config(kBoardFilterJson));
  ASSERT_EQ(in.size(), out.size());
  for (std::size_t c = 0; c < in.size(); ++c) {
    ASSERT_EQ(out[c].channel, in[c].channel);
    ASSERT_EQ(out[c].replies.size(), in[c].words.size()) << "channel " << in[c].channel;
    int non_zero = 0;
    for (std::size_t i = 0; i < in[c].words.size(); ++i) {
      const model::StepResult want = core.step(in[c].words[i], in[c].channel);
      EXPECT_EQ(out[c].replies[i].sample, want.sample) << "channel " << in[c].channel << " #" << i;
      EXPECT_EQ(out[c].replies[i].channel, in[c].channel);
      non_zero += want.sample != 0;
    }
    EXPECT_GE(non_zero, 20) << "channel " << in[c].channel << ": too short to tell channels apart";
  }
}

struct Outcome {
  int status;
  std::string out, err;
};

Outcome run(const std::vector<std::string>& args) {
  std::ostringstream out, err;
  const int status = cli::run_flange(args, out, err);
  return {status, out.str(), err.str()};
}

class BoardChannelsStream : public ::testing::Test {
 protected:
  // Three short simulated bench recordings (different seeds) and a calibration from a longer one
  // (the regression needs a range of clearances), made once.
  static void SetUpTestSuite() {
    dir_ = std::filesystem::path(FLANGE_BINARY_DIR) / "test_files" /
           ("board_channels_" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
    for (int seed : {0, 1, 2, 3}) {
      const std::string duration = seed == 0 ? "60" : "20";
      const Outcome sim =
          run({"simulate", "--scenario", "bench", "--duration", duration, "--seed",
               std::to_string(seed), "--out", path("bench_" + std::to_string(seed))});
      ASSERT_EQ(sim.status, 0) << sim.err;
    }
    const Outcome cal =
        run({"calibrate", "--data", path("bench_0"), "--out", (dir_ / "model.json").string()});
    ASSERT_EQ(cal.status, 0) << cal.err;
  }
  static void TearDownTestSuite() {
    if (!::testing::Test::HasFailure()) std::filesystem::remove_all(dir_);
  }
  static std::string path(const std::string& name) { return (dir_ / (name + ".csv")).string(); }

  static host::ChannelStreamSettings recordings(const Pty& pty, const std::vector<int>& channels) {
    host::ChannelStreamSettings s;
    s.port = pty.slave_name();
    for (std::size_t i = 0; i < channels.size(); ++i) {
      const int c = channels[i];
      s.channels.push_back(
          {c, path("bench_" + std::to_string(i % 3 + 1)), path("out_ch" + std::to_string(c)), ""});
    }
    s.calibration = (dir_ / "model.json").string();
    s.coeffs = kBoardFilterJson;
    s.source = "test manifest";
    s.link = {kBaud, 2000, 3};
    return s;
  }

  static std::filesystem::path dir_;
};
std::filesystem::path BoardChannelsStream::dir_;

TEST_F(BoardChannelsStream, InterleavedWordsMatchTheSampleBankAndTheCycleModel) {
  Pty pty;
  PtyBoard board(pty);
  host::SerialPort port(pty.slave_name(), kBaud);
  host::BoardLink link(port, {kBaud, 2000, 3});
  host::ReplyChecker checker(model::load_core_config(kBoardFilterJson));
  const std::vector<host::ChannelWords> in = channel_words(kChannels, 21);
  host::StreamCounts counts;
  const std::vector<host::ChannelReplies> out = host::stream_channels(link, in, &checker, counts);
  EXPECT_TRUE(counts.checked);
  EXPECT_EQ(counts.mismatches, 0u) << counts.first_mismatch;
  EXPECT_EQ(counts.channels, 12u);
  EXPECT_EQ(counts.samples, 12u * 90u + 3u * 66u);
  EXPECT_EQ(counts.resent, 0u);
  expect_model_outputs(in, out);
  EXPECT_FALSE(board.assertion_failed());
}

TEST_F(BoardChannelsStream, TheCheckerSeesAWrongModel) {
  // One coefficient word off in the checker's copy of the set: the library must report it.
  Pty pty;
  PtyBoard board(pty);
  host::SerialPort port(pty.slave_name(), kBaud);
  host::BoardLink link(port, {kBaud, 2000, 3});
  model::CoreConfig wrong = model::load_core_config(kBoardFilterJson);
  // The hi word of section 0's b[0] (a lo word weighs 2^-L of it: too little to show): 131 more,
  // 131 x 2^-F = 0.0020 with F = 16, so b[0]: 0.0040 -> 0.0060.
  wrong.rom.at(static_cast<std::size_t>(wrong.hi_b(0))) += 131;
  host::ReplyChecker checker(wrong);
  host::StreamCounts counts;
  host::stream_channels(link, channel_words(3, 4), &checker, counts);
  EXPECT_GT(counts.mismatches, 0u);
  // e.g. "sample 58 of channel 2: input -9877 gave 0, the model -1"
  EXPECT_NE(counts.first_mismatch.find(" gave "), std::string::npos) << counts.first_mismatch;
  EXPECT_NE(counts.first_mismatch.find(", the model "), std::string::npos) << counts.first_mismatch;
  EXPECT_NE(host::stream_summary_line(counts).find("mismatches against the model (first: "),
            std::string::npos);
}

TEST_F(BoardChannelsStream, NoisyCableWithChannelsInterleavedIsRecoveredBitExact) {
  // A bit flipped in one request, a byte lost from another (after the session reset's frame):
  // neither is answered, both are sent again on the timeout.
  Pty pty;
  constexpr std::uint64_t kFrame = host::board::kRequestBytes;
  PtyBoard board(pty, [](std::uint64_t index, std::uint8_t& byte) {
    if (index == kFrame * 30 + 2) byte ^= 0x20;  // CHANNEL of the 30th sample frame
    return index != kFrame * 77 + 4;             // SAMPLE_LO of the 77th
  });
  host::SerialPort port(pty.slave_name(), kBaud);
  host::BoardLink link(port, {kBaud, 400, 3});
  host::ReplyChecker checker(model::load_core_config(kBoardFilterJson));
  const std::vector<host::ChannelWords> in = channel_words(kChannels, 9);
  host::StreamCounts counts;
  const std::vector<host::ChannelReplies> out = host::stream_channels(link, in, &checker, counts);
  EXPECT_EQ(counts.mismatches, 0u) << counts.first_mismatch;
  EXPECT_GE(counts.resent, 2u);
  EXPECT_GE(counts.link_errors, 2u) << "the board reports the discarded bytes";
  expect_model_outputs(in, out);
}

// Each row of a channel's output CSV against the cycle model of that channel; returns the rows.
std::size_t expect_csv_matches_model(const std::string& csv, int channel) {
  model::IirCore core(model::load_core_config(kBoardFilterJson));
  std::ifstream in(csv);
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
    EXPECT_EQ(std::stoi(word_out), core.step(std::stoi(word_in), channel).sample)
        << csv << " row " << rows;
    ++rows;
  }
  return rows;
}

TEST_F(BoardChannelsStream, RecordingsOnChosenChannelsGoOutInTimeOrder) {
  Pty pty;
  PtyBoard board(pty);
  const std::vector<int> channels = {0, 5, 11};
  const host::StreamCounts counts = host::stream_channel_recordings(recordings(pty, channels));
  EXPECT_EQ(counts.mismatches, 0u) << counts.first_mismatch;
  EXPECT_EQ(counts.channels, 3u);
  std::size_t rows = 0;
  for (int c : channels) rows += expect_csv_matches_model(path("out_ch" + std::to_string(c)), c);
  EXPECT_EQ(rows, counts.samples);
  EXPECT_GT(rows, 3u * 80u);
  const std::string line = host::stream_summary_line(counts);
  EXPECT_NE(line.find("samples of 3 channels"), std::string::npos) << line;
  EXPECT_NE(line.find("; 0 mismatches against the model"), std::string::npos) << line;
}

TEST_F(BoardChannelsStream, ChannelTheBoardLacksIsRefusedWithOneLine) {
  Pty pty;
  PtyBoard board(pty);
  host::ChannelStreamSettings s = recordings(pty, {0, 12});
  s.coeffs.clear();  // only the board can say
  try {
    host::stream_channel_recordings(s);
    FAIL() << "channel 12 of a 12-channel board was accepted";
  } catch (const host::InputError& e) {
    EXPECT_EQ(std::string(e.what()), "test manifest: channel 12 is not on the board on " +
                                         pty.slave_name() + ", which serves channels 0 to 11");
  }
}

TEST_F(BoardChannelsStream, WrongCoefficientSetOrChannelListIsRefused) {
  Pty pty;
  PtyBoard board(pty);
  // Before the port is opened: a channel the set lacks, a channel twice, one beyond the link.
  host::ChannelStreamSettings s = recordings(pty, {3});
  s.port = "/dev/does-not-exist-flange";
  s.coeffs = FLANGE_SOURCE_DIR "/coeffs/measurement_sos/filter.json";
  EXPECT_THROW(
      {
        try {
          host::stream_channel_recordings(s);
        } catch (const host::InputError& e) {
          EXPECT_NE(std::string(e.what()).find("channel 3 is not in the coefficient set, which "
                                               "has channels 0 to 0"),
                    std::string::npos)
              << e.what();
          throw;
        }
      },
      host::InputError);
  s = recordings(pty, {4, 4});
  s.port = "/dev/does-not-exist-flange";
  EXPECT_THROW(host::stream_channel_recordings(s), host::InputError);
  s = recordings(pty, {256});
  s.coeffs.clear();
  s.port = "/dev/does-not-exist-flange";
  EXPECT_THROW(host::stream_channel_recordings(s), host::InputError);
  // After the reset: a one-channel set for the 12-channel board is not its bitstream's set.
  s = recordings(pty, {0});
  s.coeffs = FLANGE_SOURCE_DIR "/coeffs/measurement_sos/filter.json";
  try {
    host::stream_channel_recordings(s);
    FAIL() << "a one-channel set was taken for the 12-channel board's";
  } catch (const host::InputError&) {
    FAIL() << "a set that does not fit the board is not bad input";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("serves 12 channels, the coefficient set 1"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace flange::tb::board

namespace flange::tb::board {
namespace {

// Column `name` of a CSV, every data row.
std::vector<std::string> csv_column(const std::string& csv, const std::string& name) {
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> header;
  std::istringstream head(line);
  for (std::string field; std::getline(head, field, ',');) header.push_back(field);
  const auto column = std::find(header.begin(), header.end(), name) - header.begin();
  std::vector<std::string> values;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string field;
    for (std::ptrdiff_t k = 0; k <= column; ++k) std::getline(fields, field, ',');
    values.push_back(field);
  }
  return values;
}

TEST_F(BoardChannelsStream, TwelveWheelLocomotiveStreamsAndRunsAsTheModel) {
  // A whole locomotive as a user streams it: flange simulate --wheels 12, then flange stream
  // --manifest through the simulated 12-channel board (each wheel on its own channel, rows
  // interleaved in time), then flange run --manifest with the model: every channel's filtered
  // clearance from the board equals the run's, row for row.
  const std::string loco = (dir_ / "loco").string();
  const Outcome sim = run({"simulate", "--scenario", "loco", "--wheels", "12", "--fs", "100",
                           "--duration", "1.2", "--seed", "8", "--out", loco});
  ASSERT_EQ(sim.status, 0) << sim.err;
  const std::string manifest = loco + "/locomotive.json";
  const std::string calibration = (dir_ / "model.json").string();
  Pty pty;
  PtyBoard board(pty);
  const Outcome streamed =
      run({"stream", "--port", pty.slave_name(), "--manifest", manifest, "--calibration",
           calibration, "--coeffs", kBoardFilterJson, "--baud", std::to_string(kBaud), "--out",
           (dir_ / "loco_streamed").string()});
  ASSERT_EQ(streamed.status, 0) << streamed.err;
  EXPECT_NE(streamed.out.find("samples of 12 channels"), std::string::npos) << streamed.out;
  EXPECT_NE(streamed.out.find("; 0 mismatches against the model"), std::string::npos)
      << streamed.out;
  const Outcome ran = run({"run", "--manifest", manifest, "--calibration", calibration,
                           "--coeffs", kBoardFilterJson, "--out", (dir_ / "loco_run").string()});
  ASSERT_EQ(ran.status, 0) << ran.err;
  for (int c = 0; c < kChannels; ++c) {
    const std::string file = fmt::format("channel_{:02d}.csv", c);
    const auto board_mm = csv_column((dir_ / "loco_streamed" / file).string(), "clearance_filt_mm");
    const auto model_mm = csv_column((dir_ / "loco_run" / file).string(), "clearance_filt_mm");
    ASSERT_EQ(board_mm.size(), 121u) << "channel " << c;
    EXPECT_EQ(board_mm, model_mm) << "channel " << c;
    expect_csv_matches_model((dir_ / "loco_streamed" / file).string(), c);
  }
}

}  // namespace
}  // namespace flange::tb::board
