// SPDX-License-Identifier: MIT
// One request and its reply at a time over the Basys-3 link (docs/board.md): SEQ numbering, a
// resend (same SEQ, same CHANNEL) when the reply does not come within the timeout, the session
// reset that starts every session and reports how many channels the board's core serves.
#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <optional>
#include <string>

#include "board_frame.h"
#include "serial_port.h"

namespace flange::host {

struct LinkSettings {
  int baud = 115200;     // the bitstream's: 100 MHz / ClksPerBit (docs/board.md, "Link budget")
  int timeout_ms = 500;  // per attempt, 1..60000
  int retries = 3;       // further attempts per request before giving up, 0..100
};

struct LinkCounts {
  std::uint64_t exchanges = 0;        // sample requests answered
  std::uint64_t resent = 0;           // requests sent again after a timeout
  std::uint64_t stray_replies = 0;    // intact replies with another SEQ or CHANNEL (late or stale)
  std::uint64_t discarded_bytes = 0;  // received bytes that were part of no intact reply
};

class BoardLink {
 public:
  // `port` must outlive the link.
  BoardLink(SerialPort& port, const LinkSettings& settings);

  // Restarts the session with SEQ 0: the board resets every channel's filter and forgets the
  // last SEQ. Returns the number of channels of the board's core (1..255). Throws
  // std::runtime_error when the board does not answer or does not confirm the reset.
  int reset_session();

  // The reply to `word` on `channel` (0..255), with the next SEQ; resent on a timeout. Throws
  // std::runtime_error naming the port after retries + 1 silent attempts; `what` names the
  // request in that message (e.g. "sample 17" or "sample 17 of channel 3").
  board::Reply exchange(std::uint8_t channel, std::int16_t word, const std::string& what);

  const LinkCounts& counts() const { return counts_; }
  const std::string& device() const { return port_.device(); }

 private:
  board::Reply exchange_frame(const std::array<std::uint8_t, board::kRequestBytes>& request,
                              const board::Request& expected, const std::string& what);
  std::optional<board::Reply> await_reply(const board::Request& expected,
                                          std::chrono::milliseconds timeout);

  SerialPort& port_;
  LinkSettings settings_;
  board::ReplyScanner scanner_;
  LinkCounts counts_;
  std::uint8_t next_seq_ = 1;
};

}  // namespace flange::host
