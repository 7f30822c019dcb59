// SPDX-License-Identifier: MIT
// The link protocol of rtl/board/basys3_top.sv without its timing: the byte stream into the board
// and the replies it sends, frame by frame, with model::IirCore as the filter (docs/board.md,
// "The link"). It is the faster stand-in for the Verilated top behind a simulated USB-serial link
// (pty_board.h, bench/link_bench.cpp), where the Verilated top would measure the simulator rather
// than the link; Basys3TopModel.AnswersEveryStreamAsTheRtl checks it against the RTL byte for
// byte. Every frame is answered before the next byte is taken, so the queue never overflows
// (a host with at most 32 requests in flight never overflows the board's either) and LINK_ERROR
// goes to the next new reply formed after the discard (on the board a reply formed later, when
// frames wait in the queue). btnC is press_reset() between two bytes (with nothing in the queue);
// the switches are not modelled (sw[0] down: no bypass).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "board_frame.h"
#include "iir_core.h"

namespace flange::tb::board {

class Basys3TopModel {
 public:
  explicit Basys3TopModel(const model::CoreConfig& config) : core_(config), config_(config) {}

  // One byte from the host; the bytes of the reply it completes, if any.
  std::vector<std::uint8_t> take(std::uint8_t byte) {
    namespace frame = host::board;
    if (fill_ == frame::kRequestBytes) {
      for (std::size_t i = 1; i < fill_; ++i) window_[i - 1] = window_[i];
      window_[fill_ - 1] = byte;
      link_error_ = true;  // the oldest byte left the window unused
    } else {
      window_[fill_++] = byte;
    }
    if (fill_ < frame::kRequestBytes) return {};
    const bool sample = window_[0] == frame::kSync, command = window_[0] == frame::kCommandSync;
    if ((!sample && !command) ||
        frame::crc8(std::span<const std::uint8_t>(window_).subspan(1, 4)) != window_[5]) {
      return {};
    }
    fill_ = 0;
    const frame::Request request{
        window_[1], window_[2],
        static_cast<std::int16_t>(static_cast<std::uint16_t>((window_[3] << 8) | window_[4]))};
    const std::optional<frame::Reply> reply = command ? on_command(request) : on_sample(request);
    if (!reply) return {};
    const auto bytes = frame::encode_reply(*reply);
    return {bytes.begin(), bytes.end()};
  }

  // btnC: everything as at power-up (a plain session; the frame window, the stored replies, the
  // filters and the pending link error all cleared).
  void press_reset() { *this = Basys3TopModel(config_); }

 private:
  static constexpr int kStore = 32;  // QueueDepth of basys3_top
  struct Stored {
    bool valid = false;
    std::uint8_t channel = 0;
    std::int16_t out = 0;
    std::uint8_t status = 0;
  };

  std::optional<host::board::Reply> on_command(const host::board::Request& r) {
    namespace frame = host::board;
    const auto code = static_cast<std::uint16_t>(r.sample);
    if (code != frame::kCommandReset && code != frame::kCommandResetWindowed) return {};
    core_ = model::IirCore(config_);
    windowed_ = code == frame::kCommandResetWindowed;
    expect_ = static_cast<std::uint8_t>(r.seq + 1);
    have_seq_ = false;
    store_ = {};
    std::uint8_t status = frame::kStatusSessionReset | (windowed_ ? frame::kStatusWindowed : 0);
    if (link_error_) status |= frame::kStatusLinkError;
    link_error_ = false;
    return frame::Reply{r.seq, r.channel, static_cast<std::int16_t>(config_.num_channels), status};
  }

  std::optional<host::board::Reply> on_sample(const host::board::Request& r) {
    namespace frame = host::board;
    Stored& entry = store_[r.seq % kStore];
    const auto age = static_cast<std::uint8_t>(expect_ - r.seq);
    const bool repeat = windowed_
                            ? age != 0 && age <= kStore && entry.valid && entry.channel == r.channel
                            : have_seq_ && r.seq == last_seq_ && r.channel == last_channel_;
    if (repeat) {
      return frame::Reply{r.seq, r.channel, entry.out,
                          static_cast<std::uint8_t>(entry.status | frame::kStatusRetransmit)};
    }
    if (windowed_ && r.seq != expect_) return {};  // an earlier frame was lost
    have_seq_ = true;
    last_seq_ = r.seq;
    last_channel_ = r.channel;
    expect_ = static_cast<std::uint8_t>(r.seq + 1);
    std::uint8_t status = windowed_ ? frame::kStatusWindowed : 0;
    if (link_error_) status |= frame::kStatusLinkError;
    link_error_ = false;
    std::int16_t out = 0;
    if (r.channel >= config_.num_channels) {
      status |= frame::kStatusChannelError;
    } else {
      const model::StepResult y = core_.step(r.sample, r.channel);
      out = static_cast<std::int16_t>(y.sample);
      if (y.saturated) status |= frame::kStatusSaturation;
    }
    entry = {true, r.channel, out, status};
    return frame::Reply{r.seq, r.channel, out, status};
  }

  model::IirCore core_;
  model::CoreConfig config_;
  std::array<std::uint8_t, host::board::kRequestBytes> window_{};
  std::size_t fill_ = 0;
  bool link_error_ = false;
  bool windowed_ = false;
  bool have_seq_ = false;
  std::uint8_t last_seq_ = 0, last_channel_ = 0, expect_ = 0;
  std::array<Stored, kStore> store_{};
};

}  // namespace flange::tb::board
