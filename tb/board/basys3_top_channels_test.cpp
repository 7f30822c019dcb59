// SPDX-License-Identifier: MIT
// The 12-channel Basys-3 top (loco_ch12: the vehicle filter on 12 channels of one core) in
// Verilator, driven through its pins with the channels' samples interleaved on the one link. Every
// reply must equal the bit-accurate model of its own channel (model::IirCore::step(sample,
// channel)), with that channel's OVERRUN and SATURATION, also when frames are damaged, dropped,
// resent or name a channel the core lacks. The filter is slow (0.259 Hz at 100 Hz: its first
// non-zero output comes about 50 samples after a step), so every stream gives each channel 120 or
// more samples. Reproduce one case with
//   build/tb/basys3_top_channels_test --gtest_filter='Basys3TopChannels.<Name>'
// (FLANGE_TRACE=1 writes logs/basys3_ch12_<Name>.fst).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <map>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "board_bench.h"
#include "board_frame.h"
#include "display_text.h"
#include "filter_json.h"
#include "iir_core.h"
#include "link_budget.h"

namespace flange::tb::board {
namespace {

namespace frame = flange::host::board;

constexpr int kChannels = 12;
constexpr std::uint16_t kLedOverrun = 1u << 1;
constexpr std::uint16_t kLedSaturation = 1u << 2;
constexpr std::uint16_t kLedLinkError = 1u << 3;
constexpr std::uint16_t kLedChannelError = 1u << 5;

std::int16_t clearance_word(double mm) {
  return static_cast<std::int16_t>(std::lround((mm - 6.0) / 8.0 * 32768.0));
}

// A different clearance signal per channel (each wheel its own wear, phase and noise): levels
// 3.5 to 12.3 mm, far apart, so that a sample filtered on the wrong channel shows.
std::int16_t wheel_word(int channel, int n, std::mt19937& rng) {
  std::normal_distribution<double> noise(0.0, 0.05);
  const double mm = 3.5 + 0.8 * channel +
                    0.5 * std::sin(2.0 * M_PI * n / (15.0 + 2.0 * channel) + channel) + noise(rng);
  return clearance_word(mm);
}

// The faults a noisy cable or a confused host brings, one drawn per request.
enum class Fault {
  kNone,
  kDroppedByte,
  kFlippedBits,
  kGarbage,
  kBadStopBit,
  kLostReply,
  kNoChannel
};

Fault draw_fault(std::mt19937& rng) {
  const int p = std::uniform_int_distribution<int>(0, 99)(rng);
  if (p < 70) return Fault::kNone;
  if (p < 76) return Fault::kDroppedByte;
  if (p < 82) return Fault::kFlippedBits;
  if (p < 88) return Fault::kGarbage;
  if (p < 92) return Fault::kBadStopBit;
  if (p < 97) return Fault::kLostReply;
  return Fault::kNoChannel;
}

class Basys3TopChannels : public ::testing::Test {
 protected:
  void SetUp() override {
    std::filesystem::path fst;
    if (const char* trace = std::getenv("FLANGE_TRACE"); trace && std::string(trace) == "1") {
      fst = std::filesystem::path("logs") /
            (std::string("basys3_ch12_") +
             ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".fst");
    }
    bench_ = std::make_unique<BoardBench>(fst);
    model_ = std::make_unique<model::IirCore>(model::load_core_config(kBoardFilterJson));
    ASSERT_EQ(model_->config().num_channels, kChannels) << kBoardFilterJson;
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
  std::vector<frame::Reply> exchange(const std::vector<std::uint8_t>& bytes) {
    bench_->send(bytes);
    bench_->drain();
    return replies();
  }
  static std::vector<std::uint8_t> request(std::uint8_t seq, int channel, std::int16_t sample) {
    const auto f = frame::encode_request({seq, static_cast<std::uint8_t>(channel), sample});
    return {f.begin(), f.end()};
  }
  // Sends `sample` on `channel` (after `prefix`, bytes glued before the frame) and checks the one
  // reply against that channel's model.
  frame::Reply expect_filtered(std::uint8_t seq, int channel, std::int16_t sample,
                               std::uint8_t extra_status = 0,
                               const std::vector<std::uint8_t>& prefix = {}) {
    const model::StepResult want = model_->step(sample, channel);
    std::vector<std::uint8_t> bytes = prefix;
    const std::vector<std::uint8_t> f = request(seq, channel, sample);
    bytes.insert(bytes.end(), f.begin(), f.end());
    const std::vector<frame::Reply> got = exchange(bytes);
    EXPECT_EQ(got.size(), 1u) << "seq " << int{seq} << " channel " << channel;
    if (got.size() != 1u) return {};
    const auto status =
        static_cast<std::uint8_t>((want.saturated ? frame::kStatusSaturation : 0) | extra_status);
    EXPECT_EQ(got[0], (frame::Reply{seq, static_cast<std::uint8_t>(channel),
                                    static_cast<std::int16_t>(want.sample), status}))
        << "seq " << int{seq} << " channel " << channel << " sample " << sample;
    return got[0];
  }

  // What a damaged copy of `frame_bytes` costs: it is sent (and must get no reply), or for garbage
  // returned in `prefix` to be glued before the intact frame. Returns the bytes the board counts
  // as link errors (discarded, or with a bad stop bit).
  int send_damaged(Fault fault, const std::vector<std::uint8_t>& frame_bytes, std::mt19937& rng,
                   std::vector<std::uint8_t>& prefix);

  // A windowed session's new frame on every channel (SEQ seq, seq + 1, ...): each reply checked
  // against its channel's model, with OVERRUN where `overrun` says. Keeps the frames and replies.
  void new_frame_on_every_channel(std::uint8_t& seq, int n, std::mt19937& rng,
                                  const std::vector<bool>& overrun) {
    last_.resize(kChannels);
    stored_.resize(kChannels);
    for (int c = 0; c < kChannels; ++c) {
      last_[c] = {seq, static_cast<std::uint8_t>(c), wheel_word(c, n, rng)};
      const auto status = static_cast<std::uint8_t>(frame::kStatusWindowed |
                                                    (overrun[c] ? frame::kStatusOverrun : 0));
      stored_[c] = expect_filtered(seq++, c, last_[c].sample, status);
    }
  }
  static frame::Reply retransmitted(frame::Reply reply) {
    reply.status |= frame::kStatusRetransmit;
    return reply;
  }
  // Back to back, 700 frames: retransmissions of every channel's last frame, round robin, and
  // every 16th frame an unknown command naming the next channel (accepted and ignored, or dropped
  // without marking a channel: DroppedCommandMarksNoChannel). A reply takes longer than a request,
  // so the queue (32) fills and frames are dropped. Every reply must be a frame's stored reply
  // with RETRANSMIT, nothing else; returns, per channel, whether a retransmission of it was
  // dropped (fewer replies than were sent).
  std::vector<bool> overflow_with_retransmissions() {
    std::vector<std::uint8_t> burst;
    std::vector<int> sent(kChannels, 0), answered(kChannels, 0);
    for (int k = 0; k < 700; ++k) {
      const frame::Request& r = last_[static_cast<std::size_t>(k % kChannels)];
      const bool command = k % 16 == 15;
      const auto f =
          command ? frame::encode_command(r.seq, 0x0077, r.channel) : frame::encode_request(r);
      if (!command) ++sent[r.channel];
      burst.insert(burst.end(), f.begin(), f.end());
    }
    for (const frame::Reply& got : exchange(burst)) {
      EXPECT_LT(got.channel, kChannels);
      if (got.channel >= kChannels) continue;
      EXPECT_EQ(got, retransmitted(stored_[got.channel])) << "channel " << int{got.channel};
      ++answered[got.channel];
    }
    std::vector<bool> dropped(kChannels);
    for (int c = 0; c < kChannels; ++c) dropped[c] = answered[c] < sent[c];
    return dropped;
  }
  // One retransmission of every channel's last frame, each waited for: the reply it had, with
  // RETRANSMIT and without OVERRUN, whatever the channel has pending.
  void retransmit_each_once() {
    for (int c = 0; c < kChannels; ++c) {
      const auto f = frame::encode_request(last_[c]);
      const std::vector<frame::Reply> got = exchange({f.begin(), f.end()});
      ASSERT_EQ(got.size(), 1u) << "channel " << c;
      EXPECT_EQ(got[0], retransmitted(stored_[c])) << "channel " << c;
    }
  }

  std::unique_ptr<BoardBench> bench_;
  std::unique_ptr<model::IirCore> model_;
  std::vector<frame::Request> last_;  // every channel's last new frame (windowed tests)
  std::vector<frame::Reply> stored_;  // and its reply
};

TEST_F(Basys3TopChannels, InterleavedChannelsMatchTheModelBitForBit) {
  // 150 rounds; each round visits the 12 channels in a new random order.
  std::mt19937 rng(12);
  std::vector<int> order(kChannels);
  std::iota(order.begin(), order.end(), 0);
  std::vector<int> n(kChannels, 0);
  std::vector<std::int16_t> last(kChannels, 0);
  std::uint8_t seq = 0;
  for (int round = 0; round < 150; ++round) {
    std::shuffle(order.begin(), order.end(), rng);
    for (int c : order) last[c] = expect_filtered(seq++, c, wheel_word(c, n[c]++, rng)).sample;
  }
  EXPECT_EQ(bench_->leds() & (kLedOverrun | kLedSaturation | kLedLinkError | kLedChannelError), 0);
  // The stream is long enough for the outputs to tell the channels apart.
  for (int c = 1; c < kChannels; ++c) EXPECT_GT(last[c], last[c - 1]) << "channel " << c;
  EXPECT_NE(last[0], 0);
}

TEST_F(Basys3TopChannels, ExchangeTimeFollowsTheLinkBudgetFormula) {
  // Stop-and-wait with no host turnaround: each request leaves the moment the previous reply is
  // in. The same formula holds at ClksPerBit 109 (basys3_top_link_budget_test).
  std::mt19937 rng(2);
  const std::uint64_t start = bench_->cycle();
  constexpr int kExchanges = 48;
  for (int k = 0; k < kExchanges; ++k) {
    const int c = k % kChannels;
    const std::int16_t word = wheel_word(c, k / kChannels, rng);
    bench_->send(request(static_cast<std::uint8_t>(k), c, word));
    EXPECT_EQ(await_reply(*bench_).sample, model_->step(word, c).sample);
  }
  const double per_exchange = static_cast<double>(bench_->cycle() - start) / kExchanges;
  EXPECT_NEAR(per_exchange,
              static_cast<double>(exchange_cycles(kSimClksPerBit, model_->latency_cycles())), 1.0);
}

TEST_F(Basys3TopChannels, SaturationIsReportedOnItsOwnChannelOnly) {
  // Channel c steps from its quiet clearance to a full-scale rail (alternating signs) in round
  // 10c; the filter's overshoot clips it about 390 samples later. So at any time some channels
  // clip and others do not. Every reply's SATURATION must be its own channel's (the model's flag
  // for that sample), and every channel must have clipped at least once.
  std::mt19937 rng(5);
  std::vector<int> saturated(kChannels, 0);
  std::uint8_t seq = 0;
  for (int n = 0; n < 520; ++n) {
    for (int c = 0; c < kChannels; ++c) {
      const std::int16_t rail = c % 2 ? std::int16_t{32767} : std::int16_t{-32768};
      const std::int16_t word = n < 10 * c ? wheel_word(c, n, rng) : rail;
      saturated[c] += (expect_filtered(seq++, c, word).status & frame::kStatusSaturation) != 0;
    }
  }
  for (int c = 0; c < kChannels; ++c) EXPECT_GT(saturated[c], 0) << "channel " << c;
  EXPECT_TRUE(bench_->leds() & kLedSaturation);
}

TEST_F(Basys3TopChannels, CorruptedFramesWithChannelsInterleaved) {
  // Like a real host: a damaged request gets no reply and is sent again intact (same SEQ and
  // CHANNEL); a lost reply is asked for again with the same frame and comes back with RETRANSMIT.
  // Every answered reply must equal its channel's model, with LINK_ERROR exactly when bytes were
  // discarded or had a bad stop bit since the previous reply; the error count must add up.
  std::mt19937 rng(14);
  std::vector<int> order(kChannels);
  std::iota(order.begin(), order.end(), 0);
  std::vector<int> n(kChannels, 0);
  std::uint8_t seq = 0;
  int link_errors = 0;
  std::map<Fault, int> seen;
  for (int round = 0; round < 130; ++round) {
    std::shuffle(order.begin(), order.end(), rng);
    for (int c : order) {
      const std::int16_t word = wheel_word(c, n[c]++, rng);
      const Fault fault = draw_fault(rng);
      ++seen[fault];
      if (fault == Fault::kLostReply) {
        frame::Reply want = expect_filtered(seq, c, word);
        want.status = static_cast<std::uint8_t>(want.status | frame::kStatusRetransmit);
        const std::vector<frame::Reply> again = exchange(request(seq++, c, word));
        ASSERT_EQ(again.size(), 1u);
        EXPECT_EQ(again[0], want) << "the stored reply, not a second filtering";
        continue;
      }
      if (fault == Fault::kNoChannel) {
        const int bad = std::uniform_int_distribution<int>(kChannels, 255)(rng);
        const std::vector<frame::Reply> got = exchange(request(seq, bad, word));
        ASSERT_EQ(got.size(), 1u);
        EXPECT_EQ(got[0], (frame::Reply{seq++, static_cast<std::uint8_t>(bad), 0,
                                        frame::kStatusChannelError}));
      }
      std::vector<std::uint8_t> prefix;
      const int errors = send_damaged(fault, request(seq, c, word), rng, prefix);
      link_errors += errors;
      expect_filtered(seq++, c, word, errors > 0 ? frame::kStatusLinkError : 0, prefix);
    }
  }
  for (Fault f : {Fault::kDroppedByte, Fault::kFlippedBits, Fault::kGarbage, Fault::kBadStopBit,
                  Fault::kLostReply, Fault::kNoChannel}) {
    EXPECT_GT(seen[f], 5) << "fault " << static_cast<int>(f) << " too rare to mean much";
  }
  // sw[1]: the board's count of link errors, in hex.
  bench_->set_switches(0x2);
  bench_->run(8u << kSimRefreshBits);
  char hex[8];
  std::snprintf(hex, sizeof hex, "%04X", link_errors);
  EXPECT_EQ(bench_->display(), std::string(hex));
}

int Basys3TopChannels::send_damaged(Fault fault, const std::vector<std::uint8_t>& frame_bytes,
                                    std::mt19937& rng, std::vector<std::uint8_t>& prefix) {
  std::uniform_int_distribution<int> byte_value(0, 255);
  std::vector<std::uint8_t> broken = frame_bytes;
  switch (fault) {
    case Fault::kDroppedByte:
      broken.erase(broken.begin() + std::uniform_int_distribution<int>(0, 5)(rng));
      break;
    case Fault::kFlippedBits:
      for (int b = std::uniform_int_distribution<int>(1, 3)(rng); b > 0; --b) {
        broken[std::uniform_int_distribution<std::size_t>(0, 5)(rng)] ^=
            static_cast<std::uint8_t>(1u << std::uniform_int_distribution<int>(0, 7)(rng));
      }
      if (broken == frame_bytes) return 0;  // two flips of one bit cancelled
      break;
    case Fault::kGarbage:  // glued to the frame, with SYNC bytes among it
      for (int g = std::uniform_int_distribution<int>(1, 8)(rng); g > 0; --g) {
        prefix.push_back(g % 3 == 0 ? frame::kSync : static_cast<std::uint8_t>(byte_value(rng)));
      }
      return static_cast<int>(prefix.size());
    case Fault::kBadStopBit:
      bench_->send({static_cast<std::uint8_t>(byte_value(rng))}, /*bad_stop=*/true);
      return 1;
    default:
      return 0;
  }
  EXPECT_TRUE(exchange(broken).empty()) << "a damaged frame was answered";
  return static_cast<int>(broken.size());
}

TEST_F(Basys3TopChannels, BurstReportsOverrunOnTheDroppedFramesChannel) {
  // Back-to-back requests on random channels: a reply (7 bytes) is longer than a request (6), so
  // the queue of accepted frames (32) fills and then about every seventh frame is dropped. A
  // reply's OVERRUN says that a frame of its own channel was dropped since that channel's previous
  // reply. SEQ wraps: a reply's SEQ is its frame's index modulo 256. Every channel has a frame
  // dropped.
  std::mt19937 rng(31);
  std::uniform_int_distribution<int> any_channel(0, kChannels - 1);
  std::vector<std::pair<int, std::int16_t>> sent;  // channel, sample; the index is the SEQ
  std::vector<std::uint8_t> burst;
  std::vector<int> n(kChannels, 0);
  for (int k = 0; k < 320; ++k) {
    const int c = any_channel(rng);
    sent.emplace_back(c, wheel_word(c, n[c]++, rng));
    const std::vector<std::uint8_t> f =
        request(static_cast<std::uint8_t>(k), c, sent.back().second);
    burst.insert(burst.end(), f.begin(), f.end());
  }
  std::vector<frame::Reply> got = exchange(burst);
  // Then one frame per channel, each waited for: they report what the burst's end dropped.
  for (int c = 0; c < kChannels; ++c) {
    sent.emplace_back(c, wheel_word(c, n[c]++, rng));
    for (const frame::Reply& r :
         exchange(request(static_cast<std::uint8_t>(sent.size() - 1), c, sent.back().second))) {
      got.push_back(r);
    }
  }
  ASSERT_LT(got.size(), sent.size()) << "the burst was expected to overrun the board";
  std::vector<bool> dropped_since_reply(kChannels, false), ever_dropped(kChannels, false);
  std::size_t next = 0;  // index into got
  for (std::size_t k = 0; k < sent.size(); ++k) {
    const auto [c, word] = sent[k];
    if (next < got.size() && got[next].seq == static_cast<std::uint8_t>(k)) {
      const model::StepResult want = model_->step(word, c);
      const auto status =
          static_cast<std::uint8_t>((want.saturated ? frame::kStatusSaturation : 0) |
                                    (dropped_since_reply[c] ? frame::kStatusOverrun : 0));
      EXPECT_EQ(got[next], (frame::Reply{static_cast<std::uint8_t>(k), static_cast<std::uint8_t>(c),
                                         static_cast<std::int16_t>(want.sample), status}))
          << "frame " << k;
      dropped_since_reply[c] = false;
      ++next;
    } else {
      dropped_since_reply[c] = true;  // never filtered: the model does not step
      ever_dropped[c] = true;
    }
  }
  for (int c = 0; c < kChannels; ++c) {
    EXPECT_TRUE(ever_dropped[c]) << "no frame of channel " << c << " was dropped";
  }
  EXPECT_EQ(next, got.size()) << "replies out of order or with unknown SEQ";
  EXPECT_TRUE(bench_->leds() & kLedOverrun);
  EXPECT_FALSE(bench_->leds() & kLedLinkError);
}

TEST_F(Basys3TopChannels, DroppedCommandMarksNoChannel) {
  // A burst that overflows the frame queue: samples of channel 1, and from the 200th frame on
  // every other frame an unknown command with CHANNEL 0 (ignored when accepted). The commands
  // that find the queue full are dropped like any frame (led[1]), but their CHANNEL byte is only
  // an echo: channel 0's next reply has no OVERRUN, channel 1's has it.
  std::mt19937 rng(6);
  std::uint8_t seq = 0;
  for (int n = 0; n < 60; ++n) expect_filtered(seq++, 0, wheel_word(0, n, rng));
  std::vector<std::uint8_t> burst;
  std::vector<std::int16_t> words;  // channel 1's samples by frame index (0: a command)
  const int first = seq;
  for (int k = 0; k < 320; ++k) {
    std::array<std::uint8_t, frame::kRequestBytes> f{};
    if (k >= 200 && k % 2 == 1) {
      f = frame::encode_command(static_cast<std::uint8_t>(first + k), 0x0077, 0);
      words.push_back(0);
    } else {
      words.push_back(wheel_word(1, k, rng));
      f = frame::encode_request({static_cast<std::uint8_t>(first + k), 1, words.back()});
    }
    burst.insert(burst.end(), f.begin(), f.end());
  }
  const std::vector<frame::Reply> got = exchange(burst);
  std::size_t samples = 0;
  for (int k = 0; k < 320; ++k) samples += words[static_cast<std::size_t>(k)] != 0 ? 1 : 0;
  ASSERT_LT(got.size(), samples) << "the burst was meant to overflow the queue";
  int expected = first;
  for (const frame::Reply& r : got) {
    const int index = expected + ((r.seq - expected) & 0xFF);
    ASSERT_EQ(r.channel, 1);
    EXPECT_EQ(r.sample, model_->step(words[static_cast<std::size_t>(index - first)], 1).sample);
    expected = index + 1;
  }
  EXPECT_TRUE(bench_->leds() & kLedOverrun);
  seq = static_cast<std::uint8_t>(first + 320);
  expect_filtered(seq++, 0, wheel_word(0, 60, rng));  // STATUS 0: no OVERRUN on channel 0
  const std::int16_t word = wheel_word(1, 400, rng);
  const std::vector<frame::Reply> one = exchange(request(seq, 1, word));
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0].sample, model_->step(word, 1).sample);
  bool tail_dropped = false;  // a sample of channel 1 dropped after its last answered one
  for (int k = expected - first; k < 320; ++k)
    tail_dropped |= words[static_cast<std::size_t>(k)] != 0;
  EXPECT_EQ((one[0].status & frame::kStatusOverrun) != 0, tail_dropped);
}

TEST_F(Basys3TopChannels, OverrunBehindRetransmissionsWaitsForTheChannelsNextNewReply) {
  // A windowed session whose queue a host overflows with retransmissions and commands of every
  // channel. A dropped frame's mark rides on its channel's next accepted frame; when that is a
  // retransmission, whose reply repeats the stored STATUS, the board keeps the channel's OVERRUN
  // pending: retransmissions neither report nor clear it, the channel's next new reply reports it
  // and the one after does not. A session reset reports the whole board's pending OVERRUN and
  // clears it.
  std::mt19937 rng(46);
  std::uint8_t seq = 0;
  const auto start = frame::encode_command(seq, frame::kCommandResetWindowed);
  const std::vector<bool> none(kChannels, false), every(kChannels, true);
  ASSERT_EQ(exchange({start.begin(), start.end()}),
            (std::vector<frame::Reply>{
                {seq++, 0, kChannels, frame::kStatusSessionReset | frame::kStatusWindowed}}));
  new_frame_on_every_channel(seq, 0, rng, none);
  EXPECT_EQ(overflow_with_retransmissions(), every) << "a frame of every channel is dropped";
  retransmit_each_once();  // the marks still waiting in the queue's drop bits become pending
  retransmit_each_once();
  new_frame_on_every_channel(seq, 1, rng, every);
  new_frame_on_every_channel(seq, 2, rng, none);
  EXPECT_TRUE(bench_->leds() & kLedOverrun);

  EXPECT_EQ(overflow_with_retransmissions(), every);
  retransmit_each_once();
  const auto reset = frame::encode_command(seq, frame::kCommandResetWindowed, 5);
  ASSERT_EQ(exchange({reset.begin(), reset.end()}),
            (std::vector<frame::Reply>{
                {seq++, 5, kChannels,
                 frame::kStatusSessionReset | frame::kStatusWindowed | frame::kStatusOverrun}}));
  model_ = std::make_unique<model::IirCore>(model::load_core_config(kBoardFilterJson));
  new_frame_on_every_channel(seq, 3, rng, none);
  EXPECT_FALSE(bench_->leds() & kLedLinkError);
}

TEST_F(Basys3TopChannels, ChannelsTheCoreLacksAreAnsweredAndNeverFiltered) {
  // 12 and 15 are beyond the core's channels in its 4-bit channel_i; 16 and 255 would alias to
  // channels 0 and 15 in four bits. None may reach the filter; the real channels stay exact.
  std::mt19937 rng(3);
  std::uint8_t seq = 0;
  const int wrong[] = {12, 15, 16, 255};
  for (int n = 0; n < 120; ++n) {
    for (int c = 0; c < kChannels; ++c) {
      expect_filtered(seq++, c, wheel_word(c, n, rng));
      if ((n + c) % 9 == 1) {
        const int bad = wrong[(n + c) % 4];
        const std::vector<frame::Reply> got = exchange(request(seq, bad, clearance_word(13.0)));
        ASSERT_EQ(got.size(), 1u) << "channel " << bad;
        EXPECT_EQ(got[0], (frame::Reply{seq, static_cast<std::uint8_t>(bad), 0,
                                        frame::kStatusChannelError}));
        ++seq;
      }
    }
  }
  EXPECT_TRUE(bench_->leds() & kLedChannelError);
  EXPECT_FALSE(bench_->leds() & (kLedOverrun | kLedLinkError));
}

TEST_F(Basys3TopChannels, DisplayShowsTheChannelTheSwitchesChoose) {
  // sw[15:12] choose the channel on the display: each channel's latest output, whatever channel
  // replied last; channels 12 to 15, which the core lacks, show dashes; a session reset puts every
  // channel back to " 6.00".
  std::mt19937 rng(15);
  std::uint8_t seq = 0;
  std::vector<std::int16_t> latest(kChannels, 0);
  for (int n = 0; n < 70; ++n) {
    for (int c = 0; c < kChannels; ++c) {
      latest[c] = expect_filtered(seq++, c, wheel_word(c, n, rng)).sample;
    }
  }
  // Bypass on channel 7: its input becomes its shown value; the others keep theirs.
  bench_->set_switches(0x1);
  bench_->run(4);
  const auto bypassed = static_cast<std::int16_t>(12345);
  ASSERT_EQ(exchange(request(seq++, 7, bypassed)).size(), 1u);
  latest[7] = bypassed;
  for (int c = 0; c < 16; ++c) {
    bench_->set_switches(static_cast<std::uint16_t>(c << 12));
    bench_->run(4u + (4u << kSimRefreshBits) + 40u);  // synchroniser, conversion, a full refresh
    const std::string want = c < kChannels ? expected_display(latest[c]) : "----";
    EXPECT_EQ(bench_->display(), want) << "sw[15:12] = " << c;
  }
  const auto reset = frame::encode_command(seq, frame::kCommandReset);
  ASSERT_EQ(exchange({reset.begin(), reset.end()}).size(), 1u);
  for (int c : {0, 7, 11}) {
    bench_->set_switches(static_cast<std::uint16_t>(c << 12));
    bench_->run(4u + (4u << kSimRefreshBits) + 40u);
    EXPECT_EQ(bench_->display(), " 6.00") << "channel " << c << " after the session reset";
  }
}

TEST_F(Basys3TopChannels, SessionResetReportsTwelveChannelsAndRestartsEveryOne) {
  std::mt19937 rng(8);
  std::uint8_t seq = 0;
  for (int n = 0; n < 120; ++n) {
    for (int c = 0; c < kChannels; ++c) expect_filtered(seq++, c, wheel_word(c, n, rng));
  }
  const auto cmd = frame::encode_command(seq, frame::kCommandReset, 7);
  const std::vector<frame::Reply> got = exchange({cmd.begin(), cmd.end()});
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0], (frame::Reply{seq, 7, kChannels, frame::kStatusSessionReset}));
  model_ = std::make_unique<model::IirCore>(model::load_core_config(kBoardFilterJson));
  for (int n = 0; n < 120; ++n) {
    for (int c = kChannels - 1; c >= 0; --c) expect_filtered(seq++, c, wheel_word(c, n, rng));
  }
}

}  // namespace
}  // namespace flange::tb::board
