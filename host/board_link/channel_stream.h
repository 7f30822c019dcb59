// SPDX-License-Identifier: MIT
// Samples of several channels through the Basys-3 board as one session (docs/board.md): each
// request carries its channel, the channels' samples go out interleaved, and every reply can be
// checked against the bit-accurate model of the board's coefficient set, channel by channel
// (model::IirSampleBank: the core's channels are independent, so the interleaving does not change
// any channel's outputs). One channel is the single-recording `flange stream`.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "board_frame.h"
#include "board_link.h"
#include "filter_json.h"
#include "iir_sample_bank.h"

namespace flange::host {

struct StreamCounts {
  std::uint64_t samples = 0;
  std::uint64_t channels = 0;        // channels streamed
  std::uint64_t resent = 0;          // requests sent again after a timeout
  std::uint64_t stray_replies = 0;   // intact replies with another SEQ or CHANNEL (late or stale)
  std::uint64_t link_errors = 0;     // replies whose STATUS reports discarded bytes
  std::uint64_t overruns = 0;        // replies whose STATUS reports a dropped frame
  std::uint64_t saturated = 0;       // replies whose STATUS reports clipping
  std::uint64_t bypassed = 0;        // replies with the unfiltered input (sw[0] up)
  std::uint64_t clipped_inputs = 0;  // clearances outside the sample word's range
  std::uint64_t discarded_bytes = 0;
  std::uint64_t board_resets = 0;  // board resets during the session, recovered from by a replay
  std::uint64_t replayed = 0;      // samples sent again to rebuild the filters after them
  std::uint64_t false_frames = 0;  // damaged requests the board took, recovered by a replay
  bool checked = false;          // replies were compared with the model
  std::uint64_t mismatches = 0;  // replies that differ from the model (word or SATURATION)
  std::string first_mismatch;    // one line on the first of them
  double seconds = 0.0;          // wall time of the session
};

// The model's view of each reply: the sample bank of the board's coefficient set.
class ReplyChecker {
 public:
  // `config`: the board's set (its NumChannels and coefficients), from filter.json.
  explicit ReplyChecker(const model::CoreConfig& config) : bank_(config) {}

  int channels() const { return bank_.channels(); }
  // "" when `reply` is the model's answer to `word` on `channel` (0..channels()-1): OUT bit for
  // bit and SATURATION as the model clipped, or OUT = word with BYPASS (the model does not step);
  // otherwise one line saying what differs.
  std::string check(int channel, std::int16_t word, const board::Reply& reply);

 private:
  model::IirSampleBank bank_;
};

// Throws InputError naming `source` unless `channels` are distinct, within the link's 0..255 and,
// with a checker, within its set's channels. Returns the highest.
int check_channel_numbers(std::span<const int> channels, const ReplyChecker* checker,
                          const std::string& source);

// One session over a link: the reset that starts it, then one checked exchange per sample.
class ChannelSession {
 public:
  // Checks `channels` (check_channel_numbers), then resets the board's session. Throws InputError
  // naming `source` (the recording or manifest) when the board lacks one of the channels,
  // std::runtime_error when the board does not answer or `checker` has another channel count
  // than the board. `checker` may be null (no model check); both must outlive the session.
  ChannelSession(BoardLink& link, std::span<const int> channels, ReplyChecker* checker,
                 const std::string& source);

  // Sends `word` on `channel` (up to the link's window in flight); `on_reply` gets its reply,
  // counted and, with a checker, checked, in the order of send().
  void send(int channel, std::int16_t word, BoardLink::OnReply on_reply);
  // Waits for every reply still in flight.
  void finish() { link_.flush(); }
  int board_channels() const { return board_channels_; }
  // The counts so far (the link's resends, strays and discarded bytes included).
  StreamCounts counts() const;

 private:
  BoardLink& link_;
  ReplyChecker* checker_;
  int board_channels_ = 0;
  bool several_ = false;             // name the channel in error messages
  void take(int channel, std::int16_t word, const board::Reply& reply);

  std::vector<std::uint64_t> sent_;      // samples sent per channel
  std::vector<std::uint64_t> answered_;  // replies taken per channel
  StreamCounts counts_;
};

struct ChannelWords {
  int channel = 0;                  // 0..255, each once
  std::vector<std::int16_t> words;  // Q1.15 samples in order
};

struct ChannelReplies {
  int channel = 0;
  std::vector<board::Reply> replies;  // replies[i] answers words[i]
};

// The n-th request's position in `lengths` for round-robin interleaving: the first sample of
// every channel (in list order), then the second, ...; a channel drops out when it has no more.
std::vector<std::size_t> round_robin_order(std::span<const std::size_t> lengths);

// Streams every channel's words interleaved round robin as one session (it starts with the
// session reset) and returns each channel's replies. `checker` may be null; mismatches are
// counted in `counts` (the session goes on). Throws as ChannelSession does.
std::vector<ChannelReplies> stream_channels(BoardLink& link, std::span<const ChannelWords> channels,
                                            ReplyChecker* checker, StreamCounts& counts,
                                            const std::string& source = "the stream");

// The one-line summary `flange stream` prints. For one unchecked channel it reads as it always
// has; more channels and the model check add their figures.
std::string stream_summary_line(const StreamCounts& counts);

}  // namespace flange::host
