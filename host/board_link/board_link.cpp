// SPDX-License-Identifier: MIT
#include "board_link.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <stdexcept>
#include <utility>

namespace flange::host {

BoardLink::BoardLink(ByteStream& port, const LinkSettings& settings)
    : port_(port), settings_(settings) {
  if (settings_.window < 1 || settings_.window > kMaxWindow) {
    throw std::invalid_argument(
        fmt::format("window {} is outside 1 to {}", settings_.window, kMaxWindow));
  }
}

int BoardLink::reset_session() {
  flush();
  board::Reply reply;
  const board::Request request{0, 0, 0};
  in_flight_.emplace_back(request, board::encode_command(0, board::kCommandResetWindowed),
                          "the session reset", [&reply](const board::Reply& r) { reply = r; });
  send(in_flight_.back());
  flush();
  counts_.exchanges = 0;  // samples only
  constexpr std::uint8_t kConfirm = board::kStatusSessionReset | board::kStatusWindowed;
  if ((reply.status & kConfirm) != kConfirm) {
    throw std::runtime_error("the board on " + port_.device() +
                             " did not confirm a windowed session reset (an older bitstream?)");
  }
  if (reply.sample < 1 || reply.sample > 255) {
    throw std::runtime_error(
        fmt::format("the board on {} reports {} channels (expected 1 to 255: an older bitstream?)",
                    port_.device(), reply.sample));
  }
  next_seq_ = 1;
  return reply.sample;
}

void BoardLink::post(std::uint8_t channel, std::int16_t word, std::string what,
                     OnReply on_reply) {
  while (in_flight_.size() >= static_cast<std::size_t>(settings_.window)) pump();
  const board::Request request{next_seq_, channel, word};
  in_flight_.emplace_back(request, board::encode_request(request), std::move(what),
                          std::move(on_reply));
  next_seq_ = static_cast<std::uint8_t>(next_seq_ + 1);
  send(in_flight_.back());
}

void BoardLink::flush() {
  while (!in_flight_.empty()) pump();
}

board::Reply BoardLink::exchange(std::uint8_t channel, std::int16_t word,
                                 const std::string& what) {
  board::Reply reply;
  post(channel, word, what, [&reply](const board::Reply& r) { reply = r; });
  flush();
  return reply;
}

void BoardLink::send(InFlight& request) {
  port_.write_all(request.frame, std::chrono::milliseconds(settings_.timeout_ms));
  request.sent = std::chrono::steady_clock::now();
}

void BoardLink::pump() {
  InFlight& oldest = in_flight_.front();
  const auto deadline = oldest.sent + std::chrono::milliseconds(settings_.timeout_ms);
  const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
      deadline - std::chrono::steady_clock::now());
  if (left.count() <= 0) {
    if (oldest.attempts > settings_.retries) {
      throw std::runtime_error(fmt::format(
          "the board on {} does not answer: no reply to {} after {} attempt(s) of {} ms (is the "
          "Basys-3 programmed with the flange bitstream, is this its UART port, is the baud rate "
          "{}?)",
          port_.device(), oldest.what, settings_.retries + 1, settings_.timeout_ms,
          settings_.baud));
    }
    ++oldest.attempts;
    resend_unanswered();
    return;
  }
  std::array<std::uint8_t, 256> buffer{};
  const std::size_t n = port_.read_some(buffer, left + std::chrono::milliseconds(1));
  for (std::size_t i = 0; i < n; ++i) {
    if (std::optional<board::Reply> reply = scanner_.push(buffer[i])) take(*reply);
  }
  counts_.discarded_bytes = scanner_.discarded();
  while (!in_flight_.empty() && in_flight_.front().answered) {
    InFlight done = std::move(in_flight_.front());
    in_flight_.pop_front();
    ++counts_.exchanges;
    done.on_reply(done.reply);
  }
}

// The first reply to a request in flight is its answer; any other is stray.
void BoardLink::take(const board::Reply& reply) {
  const auto match = std::find_if(in_flight_.begin(), in_flight_.end(), [&](const InFlight& f) {
    return f.request.seq == reply.seq && f.request.channel == reply.channel;
  });
  if (match == in_flight_.end() || match->answered) {
    ++counts_.stray_replies;
    return;
  }
  if (!(reply.status & board::kStatusWindowed)) {
    throw std::runtime_error(fmt::format(
        "the board on {} was reset during the session (btnC or power): its reply to {} is not "
        "of a windowed session; {} samples were answered before it, start the session again",
        port_.device(), match->what, counts_.exchanges));
  }
  match->answered = true;
  match->reply = reply;
}

// Go-back-N: the board dropped every frame after a lost one, so every unanswered request goes
// again, in order (a request whose reply was lost is answered from the board's reply store).
void BoardLink::resend_unanswered() {
  for (InFlight& request : in_flight_) {
    if (request.answered) continue;
    ++counts_.resent;
    send(request);
  }
}

}  // namespace flange::host
