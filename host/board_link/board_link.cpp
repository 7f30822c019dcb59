// SPDX-License-Identifier: MIT
#include "board_link.h"

#include <fmt/format.h>

#include <array>
#include <chrono>
#include <stdexcept>

namespace flange::host {

BoardLink::BoardLink(SerialPort& port, const LinkSettings& settings)
    : port_(port), settings_(settings) {}

int BoardLink::reset_session() {
  const board::Request expected{0, 0, 0};
  const board::Reply reply =
      exchange_frame(board::encode_command(0, board::kCommandReset), expected, "the session reset");
  if (!(reply.status & board::kStatusSessionReset)) {
    throw std::runtime_error("the board on " + port_.device() +
                             " did not confirm the session reset (an older bitstream?)");
  }
  if (reply.sample < 1 || reply.sample > 255) {
    throw std::runtime_error(
        fmt::format("the board on {} reports {} channels (expected 1 to 255: an older bitstream?)",
                    port_.device(), reply.sample));
  }
  next_seq_ = 1;
  return reply.sample;
}

board::Reply BoardLink::exchange(std::uint8_t channel, std::int16_t word, const std::string& what) {
  const board::Request request{next_seq_, channel, word};
  const board::Reply reply = exchange_frame(board::encode_request(request), request, what);
  ++counts_.exchanges;
  next_seq_ = static_cast<std::uint8_t>(next_seq_ + 1);
  return reply;
}

board::Reply BoardLink::exchange_frame(
    const std::array<std::uint8_t, board::kRequestBytes>& request, const board::Request& expected,
    const std::string& what) {
  const std::chrono::milliseconds timeout(settings_.timeout_ms);
  for (int attempt = 0; attempt <= settings_.retries; ++attempt) {
    if (attempt > 0) ++counts_.resent;
    port_.write_all(request, timeout);
    if (std::optional<board::Reply> reply = await_reply(expected, timeout)) return *reply;
  }
  throw std::runtime_error(fmt::format(
      "the board on {} does not answer: no reply to {} after {} attempt(s) of {} ms (is the "
      "Basys-3 programmed with the flange bitstream, is this its UART port, is the baud rate "
      "{}?)",
      port_.device(), what, settings_.retries + 1, settings_.timeout_ms, settings_.baud));
}

// The reply with this SEQ and CHANNEL if it comes within the timeout; other replies are stray.
std::optional<board::Reply> BoardLink::await_reply(const board::Request& expected,
                                                   std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (true) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) return std::nullopt;
    std::array<std::uint8_t, 64> buffer{};
    const std::size_t n = port_.read_some(buffer, left);
    for (std::size_t i = 0; i < n; ++i) {
      if (std::optional<board::Reply> reply = scanner_.push(buffer[i])) {
        if (reply->seq == expected.seq && reply->channel == expected.channel) {
          counts_.discarded_bytes = scanner_.discarded();
          return reply;
        }
        ++counts_.stray_replies;
      }
    }
  }
}

}  // namespace flange::host
