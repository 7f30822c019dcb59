// SPDX-License-Identifier: MIT
// The whole Basys-3 top in Verilator, driven through its pins: frames go in bit by bit on the RX
// pin, replies are decoded bit by bit from the TX pin, and every returned sample must equal the
// bit-accurate model (model::IirCore::step) of the measurement_sos filter (one channel). Clean,
// corrupted (dropped byte, flipped bit, garbage, framing error), burst and retransmitted streams;
// channels the core lacks; bypass, reset, display and LEDs. The 12-channel board:
// basys3_top_channels_test.cpp. Reproduce one case with
//   build/tb/basys3_top_cosim_test --gtest_filter='Basys3Top.<Name>'
// (FLANGE_TRACE=1 writes logs/basys3_<Name>.fst).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "board_bench.h"
#include "board_frame.h"
#include "display_text.h"
#include "filter_json.h"
#include "iir_core.h"

namespace flange::tb::board {
namespace {

namespace frame = flange::host::board;

constexpr std::uint16_t kLedHeartbeat = 1u << 0;
constexpr std::uint16_t kLedOverrun = 1u << 1;
constexpr std::uint16_t kLedSaturation = 1u << 2;
constexpr std::uint16_t kLedLinkError = 1u << 3;
constexpr std::uint16_t kLedBypass = 1u << 4;
constexpr std::uint16_t kLedChannelError = 1u << 5;

class Basys3Top : public ::testing::Test {
 protected:
  void SetUp() override {
    std::filesystem::path fst;
    if (const char* trace = std::getenv("FLANGE_TRACE"); trace && std::string(trace) == "1") {
      fst = std::filesystem::path("logs") /
            (std::string("basys3_") +
             ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".fst");
    }
    bench_ = std::make_unique<BoardBench>(fst);
    model_ = std::make_unique<model::IirCore>(model::load_core_config(kBoardFilterJson));
  }
  void TearDown() override { EXPECT_FALSE(bench_->assertion_failed()) << "an RTL assertion fired"; }

  // Everything the TX pin sent since the last call, as replies; every byte must be part of one.
  std::vector<frame::Reply> replies() {
    std::vector<frame::Reply> out;
    frame::ReplyScanner scanner;
    auto& bytes = bench_->received();
    while (!bytes.empty()) {
      EXPECT_TRUE(bytes.front().stop_ok) << "a TX byte with a bad stop bit";
      if (auto reply = scanner.push(bytes.front().value)) out.push_back(*reply);
      bytes.pop_front();
    }
    EXPECT_EQ(scanner.discarded(), 0u) << "the board sent bytes that are no reply";
    return out;
  }

  // One frame, then wait for the link to go quiet; returns the replies seen.
  std::vector<frame::Reply> exchange(const std::vector<std::uint8_t>& bytes) {
    bench_->send(bytes);
    bench_->drain();
    return replies();
  }

  static std::vector<std::uint8_t> request(std::uint8_t seq, std::int16_t sample,
                                           std::uint8_t channel = 0) {
    const auto f = frame::encode_request({seq, channel, sample});
    return {f.begin(), f.end()};
  }

  // Sends `sample` with `seq` and checks the single reply against the model.
  // Returns whether the model saturated on it.
  bool expect_filtered(std::uint8_t seq, std::int16_t sample, std::uint8_t extra_status = 0) {
    const model::StepResult want = model_->step(sample);
    const std::vector<frame::Reply> got = exchange(request(seq, sample));
    EXPECT_EQ(got.size(), 1u) << "seq " << int{seq};
    if (got.size() != 1u) return want.saturated;
    EXPECT_EQ(got[0].seq, seq);
    EXPECT_EQ(got[0].channel, 0);
    EXPECT_EQ(got[0].sample, want.sample) << "seq " << int{seq} << " sample " << sample;
    const std::uint8_t status =
        static_cast<std::uint8_t>((want.saturated ? frame::kStatusSaturation : 0) | extra_status);
    EXPECT_EQ(got[0].status, status) << "seq " << int{seq};
    last_out_ = got[0].sample;
    return want.saturated;
  }

  void expect_display_shows(std::int16_t word) {
    bench_->run(4u << kSimRefreshBits);  // a full refresh of the four digits
    EXPECT_EQ(bench_->display(), expected_display(word));
  }

  std::unique_ptr<BoardBench> bench_;
  std::unique_ptr<model::IirCore> model_;
  std::int16_t last_out_ = 0;
};

std::int16_t clearance_word(double mm) {
  return static_cast<std::int16_t>(std::lround((mm - 6.0) / 8.0 * 32768.0));
}

TEST(Basys3TopDisplay, ExpectedTextOfTheEnds) {
  EXPECT_EQ(expected_display(0), " 6.00");
  EXPECT_EQ(expected_display(-32768), "-2.00");
  EXPECT_EQ(expected_display(32767), "14.00");
  EXPECT_EQ(expected_display(-29000), "-1.08");
  // Ties: 25 w = 512 (mod 1024), i.e. w = 512 (mod 1024): x.xx5 mm exactly, rounded up.
  EXPECT_EQ(expected_display(512), " 6.13");     // 6.125 mm
  EXPECT_EQ(expected_display(-512), " 5.88");    // 5.875 mm
  EXPECT_EQ(expected_display(-31232), "-1.62");  // -1.625 mm: half up is towards +infinity
}

TEST(Basys3TopLink, Crc8IsTheSmbusCrc) {
  const std::string check = "123456789";  // the CRC catalogue's check input
  const std::vector<std::uint8_t> bytes(check.begin(), check.end());
  EXPECT_EQ(frame::crc8(bytes), 0xF4);
  const frame::Reply reply{7, 11, -12345, frame::kStatusOverrun};
  auto encoded = frame::encode_reply(reply);
  EXPECT_EQ(frame::decode_reply(encoded), reply);
  for (std::size_t byte = 1; byte < encoded.size(); ++byte) {  // the CRC covers CHANNEL too
    auto damaged = encoded;
    damaged[byte] ^= 0x10;
    EXPECT_FALSE(frame::decode_reply(damaged)) << "byte " << byte;
  }
  // Request: SYNC, SEQ, CHANNEL, SAMPLE_HI, SAMPLE_LO, CRC-8 of the four between.
  const auto request = frame::encode_request({0x12, 0x03, -2});
  const std::vector<std::uint8_t> middle = {0x12, 0x03, 0xFF, 0xFE};
  EXPECT_EQ(request[0], frame::kSync);
  EXPECT_TRUE(std::equal(middle.begin(), middle.end(), request.begin() + 1));
  EXPECT_EQ(request[5], frame::crc8(middle));
}

TEST_F(Basys3Top, CleanStreamMatchesModelBitForBit) {
  std::mt19937 rng(4);
  std::normal_distribution<double> noise(0.0, 0.05);
  for (int n = 0; n < 300; ++n) {
    const double mm = 7.0 + 1.5 * std::sin(2.0 * M_PI * n / 40.0) + noise(rng);
    expect_filtered(static_cast<std::uint8_t>(n), clearance_word(mm));
  }
  EXPECT_EQ(bench_->leds() & (kLedOverrun | kLedSaturation | kLedLinkError), 0);
  expect_display_shows(last_out_);
  // The clearance passed through the low-pass: close to the input's 7 mm mean (not exact).
  EXPECT_NEAR(6.0 + 8.0 * last_out_ / 32768.0, 7.0, 1.6);
}

TEST_F(Basys3Top, FullScaleSaturatesAndTheStatusSaysSo) {
  // A full-scale square wave makes the Butterworth overshoot clip.
  int saturated = 0;
  for (int n = 0; n < 120; ++n) {
    const std::int16_t sample = ((n / 20) % 2) ? std::int16_t{32767} : std::int16_t{-32768};
    if (expect_filtered(static_cast<std::uint8_t>(n), sample)) ++saturated;
  }
  EXPECT_GT(saturated, 0) << "the stimulus was meant to clip";
  EXPECT_TRUE(bench_->leds() & kLedSaturation);
  EXPECT_FALSE(bench_->leds() & kLedOverrun);
}

TEST_F(Basys3Top, DroppedByteLosesOnlyThatFrame) {
  for (int n = 0; n < 10; ++n) expect_filtered(static_cast<std::uint8_t>(n), clearance_word(7.5));
  std::vector<std::uint8_t> broken = request(10, clearance_word(9.0));
  broken.erase(broken.begin() + 3);  // SAMPLE_HI lost on the wire
  EXPECT_TRUE(exchange(broken).empty()) << "a broken frame must get no reply";
  // The next intact frame is answered at once; its STATUS reports the link error.
  expect_filtered(11, clearance_word(7.6), frame::kStatusLinkError);
  expect_filtered(12, clearance_word(7.7));
  EXPECT_TRUE(bench_->leds() & kLedLinkError);
  // sw[1]: the display shows the link-error count: the 5 bytes of the broken frame.
  bench_->set_switches(0x2);
  bench_->run(4u << kSimRefreshBits);
  bench_->run(4u << kSimRefreshBits);
  EXPECT_EQ(bench_->display(), "0005");
}

TEST_F(Basys3Top, FlippedBitsAreNeverReturnedAsValid) {
  std::mt19937 rng(9);
  std::uniform_int_distribution<int> byte_pick(0, 5);
  std::uniform_int_distribution<int> bit_pick(0, 7);
  std::uint8_t seq = 0;
  int corrupted = 0;
  for (int n = 0; n < 60; ++n) {
    if (n % 3 == 2) {
      std::vector<std::uint8_t> bad = request(seq, clearance_word(8.0 + 0.01 * n));
      bad[static_cast<std::size_t>(byte_pick(rng))] ^=
          static_cast<std::uint8_t>(1u << bit_pick(rng));
      EXPECT_TRUE(exchange(bad).empty()) << "corrupted frame " << n << " was answered";
      ++corrupted;
      ++seq;  // the host moves on: that sample is lost, counted, never filtered
      bench_->send(request(seq, clearance_word(8.0)));
      bench_->drain();
      const std::vector<frame::Reply> got = replies();
      const model::StepResult want = model_->step(clearance_word(8.0));
      ASSERT_EQ(got.size(), 1u);
      EXPECT_EQ(got[0].sample, want.sample);
      EXPECT_EQ(got[0].status, frame::kStatusLinkError);
    } else {
      expect_filtered(seq, clearance_word(8.0 + 0.01 * n));
    }
    ++seq;
  }
  EXPECT_EQ(corrupted, 20);
  EXPECT_TRUE(bench_->leds() & kLedLinkError);
}

TEST_F(Basys3Top, GarbageBetweenFramesIncludingSyncBytes) {
  expect_filtered(0, clearance_word(6.5));
  // Garbage with fake SYNC bytes, a fake frame with a wrong CRC, and a framing error.
  bench_->send({0x00, 0xA5, 0xA5, 0x13, 0xA5, 0x01, 0x02, 0x03, 0x04, 0xFF});
  bench_->send({0x55}, /*bad_stop=*/true);
  expect_filtered(1, clearance_word(6.6), frame::kStatusLinkError);
  expect_filtered(2, clearance_word(6.7));
  // Garbage right before a frame with no idle time between them.
  bench_->send({0xA5, 0x02});
  expect_filtered(3, clearance_word(6.8), frame::kStatusLinkError);
  bench_->set_switches(0x2);
  bench_->run(8u << kSimRefreshBits);
  // 10 garbage bytes + 1 framing error + 2 garbage bytes.
  EXPECT_EQ(bench_->display(), "000D");
}

TEST_F(Basys3Top, BurstFasterThanTheBoardIsDroppedAndReported) {
  // Back-to-back frames: a reply (7 bytes) takes longer than a request (6 bytes), so the queue of
  // accepted frames (32) fills after about 7 x 32 of them; a frame that finds it full is dropped,
  // as the core drops an EN while busy, and the next reply carries the overrun bit. SEQ wraps.
  constexpr int kBurst = 260;
  std::vector<std::uint8_t> burst;
  std::vector<std::int16_t> samples;
  for (int n = 0; n < kBurst; ++n) {
    samples.push_back(clearance_word(7.0 + 0.01 * (n % 200)));
    const auto f = request(static_cast<std::uint8_t>(n), samples.back());
    burst.insert(burst.end(), f.begin(), f.end());
  }
  bench_->send(burst);
  bench_->drain();
  std::vector<frame::Reply> got = replies();
  // One more frame after the burst: reports any drop at the end of the burst.
  bench_->send(request(static_cast<std::uint8_t>(kBurst), clearance_word(7.0)));
  samples.push_back(clearance_word(7.0));
  bench_->drain();
  for (const frame::Reply& r : replies()) got.push_back(r);

  ASSERT_GT(got.size(), 200u) << "the queue takes most of the burst";
  EXPECT_LT(got.size(), samples.size()) << "the burst was expected to overrun the board";
  int expected = 0;  // the index of the next frame; a reply's SEQ is its index modulo 256
  for (const frame::Reply& r : got) {
    const int index = expected + ((r.seq - expected) & 0xFF);
    ASSERT_LT(index, static_cast<int>(samples.size())) << "replies out of order";
    const bool gap = index != expected;
    EXPECT_EQ((r.status & frame::kStatusOverrun) != 0, gap)
        << "frame " << index << ": a dropped frame must be reported, and only then";
    const model::StepResult want = model_->step(samples[static_cast<std::size_t>(index)]);
    EXPECT_EQ(r.sample, want.sample) << "frame " << index;
    expected = index + 1;
  }
  EXPECT_EQ(expected, kBurst + 1);
  EXPECT_TRUE(bench_->leds() & kLedOverrun);
  EXPECT_FALSE(bench_->leds() & kLedLinkError);
}

TEST_F(Basys3Top, ChannelTheCoreLacksIsAnsweredAndNeverFiltered) {
  // The measurement filter has one channel. Channel 2 would be channel 0 in the core's 1-bit
  // channel_i: the board compares all eight bits of CHANNEL.
  for (int n = 0; n < 5; ++n) expect_filtered(static_cast<std::uint8_t>(n), clearance_word(8.0));
  expect_display_shows(last_out_);
  std::uint8_t seq = 5;
  for (const int c : {1, 2, 128, 255}) {
    const auto channel = static_cast<std::uint8_t>(c);
    const std::vector<frame::Reply> got = exchange(request(seq, clearance_word(12.0), channel));
    ASSERT_EQ(got.size(), 1u) << "channel " << int{channel};
    EXPECT_EQ(got[0], (frame::Reply{seq, channel, 0, frame::kStatusChannelError}));
    ++seq;
  }
  EXPECT_TRUE(bench_->leds() & kLedChannelError);
  expect_display_shows(last_out_);  // the display keeps the last filtered sample
  // A lost reply to it is sent again like any other; the filter never sees the sample.
  const std::vector<frame::Reply> again = exchange(request(8, clearance_word(12.0), 255));
  ASSERT_EQ(again.size(), 1u);
  EXPECT_EQ(again[0].status, frame::kStatusChannelError | frame::kStatusRetransmit);
  // The last SEQ with another CHANNEL is a new frame, not a retransmission.
  expect_filtered(8, clearance_word(8.0));
  for (int n = 9; n < 14; ++n) expect_filtered(static_cast<std::uint8_t>(n), clearance_word(8.0));
  EXPECT_EQ(bench_->leds() & (kLedOverrun | kLedSaturation | kLedLinkError), 0);
  bench_->press_reset();
  EXPECT_FALSE(bench_->leds() & kLedChannelError);
}

TEST_F(Basys3Top, RetransmissionRepeatsTheReplyWithoutFilteringAgain) {
  expect_filtered(0, clearance_word(7.0));
  expect_filtered(1, clearance_word(9.0));
  const std::vector<frame::Reply> again = exchange(request(1, clearance_word(9.0)));
  ASSERT_EQ(again.size(), 1u);
  EXPECT_EQ(again[0].seq, 1);
  EXPECT_EQ(again[0].sample, last_out_);
  EXPECT_EQ(again[0].status, frame::kStatusRetransmit);
  expect_filtered(2, clearance_word(9.0));  // the model stepped once for seq 1: still equal
}

TEST_F(Basys3Top, BypassReturnsTheInputAndFreezesTheFilter) {
  for (int n = 0; n < 5; ++n) expect_filtered(static_cast<std::uint8_t>(n), clearance_word(8.0));
  bench_->set_switches(0x1);
  bench_->run(4);
  EXPECT_TRUE(bench_->leds() & kLedBypass);
  const std::int16_t words[] = {-32768, 32767, 0, -29000, 12345, 511, -1, 1};
  std::uint8_t seq = 5;
  for (std::int16_t w : words) {
    const std::vector<frame::Reply> got = exchange(request(seq, w));
    ASSERT_EQ(got.size(), 1u);
    EXPECT_EQ(got[0].sample, w);
    EXPECT_EQ(got[0].status, frame::kStatusBypass);
    expect_display_shows(w);
    ++seq;
  }
  bench_->set_switches(0x0);
  bench_->run(4);
  for (int n = 0; n < 5; ++n) expect_filtered(seq++, clearance_word(8.0));
}

TEST_F(Basys3Top, DisplayRoundsHalfUpForEveryWordClass) {
  // In bypass the display shows the word sent: a sweep over the whole range, including the
  // exact ties of the rounding (25 w = 512 mod 1024).
  bench_->set_switches(0x1);
  bench_->run(4);
  std::mt19937 rng(3);
  std::uniform_int_distribution<int> any(-32768, 32767);
  std::vector<std::int16_t> words = {-32768, -32767, -32000, -1,   0,      1,    32767,
                                     20,     -20,    512,    -512, -31232, 1536, 31232};
  for (int i = 0; i < 20; ++i) words.push_back(static_cast<std::int16_t>(any(rng)));
  std::uint8_t seq = 0;
  for (std::int16_t w : words) {
    ASSERT_EQ(exchange(request(seq++, w)).size(), 1u);
    expect_display_shows(w);
  }
}

TEST_F(Basys3Top, CentreButtonResetsFilterFlagsAndDisplay) {
  for (int n = 0; n < 20; ++n) expect_filtered(static_cast<std::uint8_t>(n), clearance_word(9.0));
  bench_->send({0x12, 0x34});
  bench_->send(request(20, clearance_word(9.0)));
  bench_->drain();
  replies();
  EXPECT_TRUE(bench_->leds() & kLedLinkError);
  bench_->press_reset();
  EXPECT_EQ(bench_->leds() & (kLedOverrun | kLedSaturation | kLedLinkError), 0);
  expect_display_shows(0);  // " 6.00": the output register is 0 after reset
  model_ = std::make_unique<model::IirCore>(model::load_core_config(kBoardFilterJson));
  // After reset the board has no last SEQ: 20 again is a new sample, not a retransmission.
  for (int n = 20; n < 30; ++n) expect_filtered(static_cast<std::uint8_t>(n), clearance_word(9.0));
}

TEST_F(Basys3Top, CentreButtonClearsTheOverrunAndSaturationLeds) {
  // Both sticky LEDs lit (a clipping full-scale edge, then a burst that overflows the frame
  // queue), OVERRUN in the replies after the gaps only, STATUS back to 0 in the reply after the
  // burst's, and btnC puts both LEDs out.
  bool saturated = false;
  for (int n = 0; n < 40; ++n) {
    const std::int16_t sample = n < 20 ? std::int16_t{-32768} : std::int16_t{32767};
    saturated = expect_filtered(static_cast<std::uint8_t>(n), sample) || saturated;
  }
  ASSERT_TRUE(saturated) << "the full-scale edge was meant to clip";
  constexpr int kBurst = 250;  // SEQ 40 to 289, modulo 256
  std::vector<std::uint8_t> burst;
  for (int k = 40; k < 40 + kBurst; ++k) {
    const std::vector<std::uint8_t> f = request(static_cast<std::uint8_t>(k), clearance_word(8.0));
    burst.insert(burst.end(), f.begin(), f.end());
  }
  const std::vector<frame::Reply> got = exchange(burst);
  ASSERT_LT(got.size(), static_cast<std::size_t>(kBurst)) << "the burst was meant to overflow";
  int expected = 40;
  for (const frame::Reply& r : got) {
    const int index = expected + ((r.seq - expected) & 0xFF);
    EXPECT_EQ((r.status & frame::kStatusOverrun) != 0, index != expected) << "frame " << index;
    EXPECT_EQ(r.sample, model_->step(clearance_word(8.0)).sample) << "frame " << index;
    expected = index + 1;
  }
  // Every reply so far reported its own gap; the next ones have STATUS 0 (or OVERRUN once, if
  // the burst's last frames were dropped).
  const std::uint8_t next = static_cast<std::uint8_t>(40 + kBurst);
  const bool tail_dropped = expected != 40 + kBurst;
  expect_filtered(next, clearance_word(8.0), tail_dropped ? frame::kStatusOverrun : 0);
  expect_filtered(static_cast<std::uint8_t>(next + 1), clearance_word(8.0));
  EXPECT_EQ(bench_->leds() & (kLedOverrun | kLedSaturation), kLedOverrun | kLedSaturation);
  bench_->press_reset();
  EXPECT_EQ(bench_->leds() & (kLedOverrun | kLedSaturation | kLedLinkError), 0);
}

TEST_F(Basys3Top, SessionResetCommandRestartsTheFilter) {
  for (int n = 0; n < 30; ++n) expect_filtered(static_cast<std::uint8_t>(n), clearance_word(9.5));
  // The reset command with the SEQ of the last sample: a command, never a retransmission.
  const auto cmd = frame::encode_command(29, frame::kCommandReset);
  const std::vector<frame::Reply> got = exchange({cmd.begin(), cmd.end()});
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0].seq, 29);
  EXPECT_EQ(got[0].channel, 0);
  EXPECT_EQ(got[0].sample, 1) << "OUT of a session reset: the core's channel count";
  EXPECT_EQ(got[0].status, frame::kStatusSessionReset);
  expect_display_shows(0);
  // A fresh model from here; SEQ 29 again is a new sample after the reset.
  model_ = std::make_unique<model::IirCore>(model::load_core_config(kBoardFilterJson));
  for (int n = 29; n < 40; ++n) expect_filtered(static_cast<std::uint8_t>(n), clearance_word(7.0));
  // An unknown command, or a reset with a bad CRC, is not answered and changes nothing.
  auto unknown = frame::encode_command(40, 0x1234);
  EXPECT_TRUE(exchange({unknown.begin(), unknown.end()}).empty());
  auto damaged = frame::encode_command(41, frame::kCommandReset);
  damaged[3] ^= 0x01;
  EXPECT_TRUE(exchange({damaged.begin(), damaged.end()}).empty());
  expect_filtered(42, clearance_word(7.0), frame::kStatusLinkError);
}

TEST_F(Basys3Top, LinkErrorCountShowsEveryHexDigitAndHoldsAtFfff) {
  // sw[1]: the display shows the link-error count in hex (docs/board.md: saturating at FFFF).
  // A byte with a low stop bit is one link error and never reaches the frame decoder.
  bench_->set_switches(0x2);
  const auto errors = [&](int n) {
    while (n > 0) {
      const int chunk = std::min(n, 4096);  // bounds the queued line levels
      for (int i = 0; i < chunk; ++i) {
        bench_->send({0xFF}, /*bad_stop=*/true);
        bench_->idle(1);
      }
      bench_->drain(2);
      n -= chunk;
    }
    bench_->run(4u << kSimRefreshBits);  // a full refresh of the four digits
  };
  const auto hex = [](int count) {
    char text[8];
    std::snprintf(text, sizeof text, "%04X", count);
    return std::string(text);
  };
  int count = 0;
  for (; count < 0x1F; ++count) {  // every hex digit in the rightmost place, 1 in the next
    errors(1);
    EXPECT_EQ(bench_->display(), hex(count + 1));
  }
  // Up to one below the top (every count bit rises and, from 0x7FFF to 0x8000, falls), then over
  // it: the count stops at FFFF instead of wrapping to 0000.
  errors(0xFFFE - count);
  EXPECT_EQ(bench_->display(), "FFFE");
  errors(1);
  EXPECT_EQ(bench_->display(), "FFFF");
  errors(3);
  EXPECT_EQ(bench_->display(), "FFFF");
  EXPECT_TRUE(replies().empty()) << "a byte with a bad stop bit must get no reply";
  // The link still works, and the next reply reports the errors; btnC clears the count.
  expect_filtered(0, clearance_word(8.0), frame::kStatusLinkError);
  EXPECT_TRUE(bench_->leds() & kLedLinkError);  // set with the reply that reports the errors
  bench_->press_reset();
  bench_->run(4u << kSimRefreshBits);
  EXPECT_EQ(bench_->display(), "0000");
}

TEST_F(Basys3Top, StartBitGlitchIsIgnored) {
  // A low pulse shorter than half a bit (4 cycles here, plus the 2-cycle synchroniser) is no
  // start bit: no byte, no link error, and the next frame is answered as if nothing happened.
  for (int n = 0; n < 3; ++n) expect_filtered(static_cast<std::uint8_t>(n), clearance_word(7.0));
  for (int cycles = 1; cycles <= kSimClksPerBit / 2 - 1; ++cycles) {
    bench_->glitch(cycles);
    bench_->drain();
    EXPECT_TRUE(replies().empty());
    expect_filtered(static_cast<std::uint8_t>(2 + cycles), clearance_word(7.0 + 0.1 * cycles));
  }
  EXPECT_FALSE(bench_->leds() & kLedLinkError);
}

TEST_F(Basys3Top, UnusedSwitchesChangeNothing) {
  // sw[11:2] are not connected (sw[1] shows the error count, sw[0] bypasses, sw[15:12] choose the
  // displayed channel): all of them up or down, the replies stay bit-exact, the display shows the
  // clearance, the LEDs stay dark.
  constexpr std::uint16_t kSwitches[] = {0x0FFC, 0x0000, 0x0AA8, 0x0554, 0x0000};
  std::uint8_t seq = 0;
  for (const std::uint16_t sw : kSwitches) {
    bench_->set_switches(sw);
    bench_->run(4);
    for (int n = 0; n < 4; ++n) expect_filtered(seq++, clearance_word(6.5 + 0.2 * n));
    EXPECT_EQ(bench_->leds() & ~kLedHeartbeat, 0) << "sw " << sw;
    expect_display_shows(last_out_);
  }
}

TEST_F(Basys3Top, HeartbeatBlinks) {
  int toggles = 0;
  bool last = bench_->leds() & kLedHeartbeat;
  for (int i = 0; i < 8 << kSimHeartbeatBit; ++i) {
    bench_->tick();
    const bool now = bench_->leds() & kLedHeartbeat;
    toggles += now != last;
    last = now;
  }
  EXPECT_GE(toggles, 7);
  EXPECT_LE(toggles, 9);
}

}  // namespace
}  // namespace flange::tb::board
