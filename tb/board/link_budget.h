// SPDX-License-Identifier: MIT
// The link budget of the board (docs/board.md, "Link budget"): how long one stop-and-wait exchange
// takes on the pins, by formula and as measured on a BoardBench.
#pragma once

#include <cstdint>
#include <optional>

#include "board_bench.h"
#include "board_frame.h"

namespace flange::tb::board {

// A request (6 bytes) and its reply (7 bytes) are 130 bit times on the wire. The board's receiver
// takes the request's last byte in the middle of its stop bit, and the host's has the reply's last
// byte in the middle of its stop bit, so a host that sends the next request at once starts it 129
// bit times after the previous one, plus the board's turnaround: 17 cycles of receiver, frame check
// and its register, frame queue, its head register and the head's classification register, and
// encoder, and the core's latency (52 cycles for the vehicle filter, docs/core.md).
inline constexpr int kLinkBitsPerExchange = 129;
inline constexpr int kBoardTurnaroundCycles = 17;

inline std::int64_t exchange_cycles(int clks_per_bit, int core_latency_cycles) {
  return std::int64_t{kLinkBitsPerExchange} * clks_per_bit + kBoardTurnaroundCycles +
         core_latency_cycles;
}

// Runs the bench until the whole reply to the request just queued has been decoded from the TX
// pin (its last byte in the middle of its stop bit, as a host's UART has it).
inline host::board::Reply await_reply(BoardBench& bench) {
  host::board::ReplyScanner scanner;
  while (true) {
    bench.tick();
    auto& bytes = bench.received();
    while (!bytes.empty()) {
      const std::optional<host::board::Reply> reply = scanner.push(bytes.front().value);
      bytes.pop_front();
      if (reply) return *reply;
    }
  }
}

}  // namespace flange::tb::board
