// SPDX-License-Identifier: MIT
// The timing of an FTDI USB-serial chip (the Basys-3's FT2232HQ) between a host and the board's
// UART pins, in wall-clock time, so that the host code's real reads and timeouts see it:
// - host -> board: a write reaches the chip `turnaround` after the host made it (the host's USB
//   stack and the OUT transfer's scheduling), then goes onto the wire at the baud rate;
// - board -> host: bytes leave the wire at the baud rate into the chip's buffer, which goes to the
//   host only at a USB frame boundary (every 1 ms) and only as a full packet (62 data bytes: 64
//   minus the two modem-status bytes) or, when the latency timer has run out since the previous
//   packet, as a short one; the chip sends a (status-only) packet at every expiry, so the timer
//   runs periodically from the last packet (FTDI AN232B-04, "latency timer").
// Header only; tb/board/pty_board.h puts it between a pseudo-terminal and the Verilated board.
#pragma once

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <deque>
#include <utility>
#include <vector>

namespace flange::tb::board {

struct FtdiSettings {
  int baud = 921600;                            // the wire's bit rate
  std::chrono::milliseconds latency_timer{16};  // 1..255 ms; Linux's default is 16
  std::chrono::microseconds turnaround{250};    // host write -> chip
};

inline constexpr std::size_t kFtdiPacketBytes = 62;  // data bytes of a 64-byte bulk IN packet
inline constexpr std::chrono::microseconds kUsbFrame{1000};

class FtdiLink {
 public:
  using Clock = std::chrono::steady_clock;
  using Time = Clock::time_point;

  FtdiLink(const FtdiSettings& settings, Time start)
      : settings_(settings),
        byte_time_(std::chrono::nanoseconds(10'000'000'000LL / settings.baud)),
        frame_start_(start),
        last_packet_(start),
        rx_wire_free_(start),
        tx_wire_free_(start) {}

  // Bytes the host wrote at `now`.
  void from_host(const std::vector<std::uint8_t>& bytes, Time now) {
    Time at = std::max(now + settings_.turnaround, rx_wire_free_);
    for (std::uint8_t byte : bytes) {
      at += byte_time_;
      to_board_.emplace_back(at, byte);
    }
    rx_wire_free_ = at;
  }
  // The bytes whose stop bit has left the wire towards the board by `now`.
  std::vector<std::uint8_t> to_board(Time now) { return take_due(to_board_, now); }

  // Bytes the board's TX pin sent, decoded at `now`.
  void from_board(const std::vector<std::uint8_t>& bytes, Time now) {
    Time at = std::max(now, tx_wire_free_);
    for (std::uint8_t byte : bytes) {
      at += byte_time_;
      on_wire_.emplace_back(at, byte);
    }
    tx_wire_free_ = at;
  }
  // The chip hands the host nothing before `until` (a host whose USB stack stops polling it for
  // a while), then catches up: what the board sent meanwhile goes at once, in full packets and
  // a short one. A later `until` extends the hold; an earlier one changes nothing.
  void hold_until(Time until) { hold_until_ = std::max(hold_until_, until); }
  bool holding(Time now) const { return now < hold_until_; }

  // The packets the chip has handed to the host by `now`, as one byte string.
  std::vector<std::uint8_t> to_host(Time now) {
    std::vector<std::uint8_t> out;
    if (holding(now)) return out;
    while (frame_start_ + kUsbFrame <= now) {
      frame_start_ += kUsbFrame;
      for (std::uint8_t byte : take_due(on_wire_, frame_start_)) buffer_.push_back(byte);
      while (buffer_.size() >= kFtdiPacketBytes) release(kFtdiPacketBytes, out);
      if (frame_start_ - last_packet_ >= settings_.latency_timer) release(buffer_.size(), out);
    }
    return out;
  }

  // When something is due next (a byte for the board, a frame with data for the host); `idle`
  // when nothing is pending.
  Time next_event(Time idle) const {
    Time next = idle;
    if (!to_board_.empty()) next = std::min(next, to_board_.front().first);
    if (!on_wire_.empty() || !buffer_.empty()) {
      next = std::min(next, std::max(frame_start_ + kUsbFrame, hold_until_));
    }
    return next;
  }

 private:
  using Timed = std::deque<std::pair<Time, std::uint8_t>>;

  static std::vector<std::uint8_t> take_due(Timed& queue, Time now) {
    std::vector<std::uint8_t> due;
    while (!queue.empty() && queue.front().first <= now) {
      due.push_back(queue.front().second);
      queue.pop_front();
    }
    return due;
  }
  // One packet of `count` buffered bytes (0: the status bytes alone) at this frame.
  void release(std::size_t count, std::vector<std::uint8_t>& out) {
    out.insert(out.end(), buffer_.begin(), buffer_.begin() + static_cast<std::ptrdiff_t>(count));
    buffer_.erase(buffer_.begin(), buffer_.begin() + static_cast<std::ptrdiff_t>(count));
    last_packet_ = frame_start_;
  }

  FtdiSettings settings_;
  std::chrono::nanoseconds byte_time_;  // ten bit times (8N1)
  Time frame_start_;                    // the last USB frame boundary handled
  Time last_packet_;                    // the latency timer restarts here
  Time rx_wire_free_, tx_wire_free_;    // when each wire's last byte ends
  Time hold_until_{};                   // nothing goes to the host before it
  Timed to_board_, on_wire_;
  std::deque<std::uint8_t> buffer_;  // in the chip, waiting for a packet
};

}  // namespace flange::tb::board
