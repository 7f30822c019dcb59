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

namespace {

// A reset (or a false frame) seen while a recovery replays the session: the recovery starts
// again.
struct ResetDuringRecovery {
  bool board_reset = true;
};

bool is_command(const std::array<std::uint8_t, board::kRequestBytes>& frame) {
  return frame[0] == board::kCommandSync;
}

}  // namespace

int BoardLink::reset_session() {
  flush();
  board_channels_ = restart_board();
  taken_.clear();
  counts_.exchanges = 0;  // samples only
  return board_channels_;
}

int BoardLink::restart_board() {
  board::Reply reply;
  const board::Request request{0, 0, 0};
  in_flight_.emplace_back(request, board::encode_command(0, board::kCommandResetWindowed),
                          "the session reset", [&reply](const board::Reply& r) { reply = r; });
  send(in_flight_.back());
  flush();
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
  enqueue(channel, word, std::move(what), std::move(on_reply), false);
}

void BoardLink::enqueue(std::uint8_t channel, std::int16_t word, std::string what,
                        OnReply on_reply, bool replay) {
  while (in_flight_.size() >= static_cast<std::size_t>(settings_.window)) pump();
  const board::Request request{next_seq_, channel, word};
  in_flight_.emplace_back(request, board::encode_request(request), std::move(what),
                          std::move(on_reply));
  in_flight_.back().replay = replay;
  next_seq_ = static_cast<std::uint8_t>(next_seq_ + 1);
  send(in_flight_.back());
}

void BoardLink::recover_from_reset(bool board_reset) {
  // The requests in flight go again once the filters are rebuilt: what the board answered them
  // so far may be its fresh filters'.
  std::deque<InFlight> pending;
  for (InFlight& request : in_flight_) {
    if (!request.replay && !is_command(request.frame)) pending.push_back(std::move(request));
  }
  recovering_ = true;
  try {
    for (;;) {
      in_flight_.clear();
      if (!board_reset) {
        ++counts_.false_frames;
      } else if (++counts_.board_resets > kMostBoardResets) {
        throw std::runtime_error(fmt::format(
            "the board on {} was reset {} times during the session (btnC or power); each reset "
            "replays the session, so the link gives up: check the board's supply and its button",
            port_.device(), counts_.board_resets));
      }
      try {
        const int channels = restart_board();
        if (channels != board_channels_) {
          throw std::runtime_error(fmt::format(
              "the board on {} was reset during the session and then reports {} channels, {} "
              "before: another bitstream?",
              port_.device(), channels, board_channels_));
        }
        replay_taken();
        break;
      } catch (const ResetDuringRecovery& again) {
        board_reset = again.board_reset;
      }
    }
  } catch (...) {
    recovering_ = false;
    throw;
  }
  recovering_ = false;
  for (InFlight& request : pending) {
    request.request.seq = next_seq_;
    next_seq_ = static_cast<std::uint8_t>(next_seq_ + 1);
    request.frame = board::encode_request(request.request);
    request.answered = false;
    request.attempts = 1;
    in_flight_.push_back(std::move(request));
    send(in_flight_.back());
  }
}

// Every sample taken since the session began, again, each reply checked against the one taken:
// the board's filters are deterministic, so the same inputs from zero give the same outputs.
void BoardLink::replay_taken() {
  for (std::size_t i = 0; i < taken_.size(); ++i) {
    const TakenSample sample = taken_[i];
    enqueue(sample.channel, sample.word, fmt::format("sample {} of the replay", i),
            [this, sample, i](const board::Reply& reply) {
              constexpr std::uint8_t kCompared = board::kStatusSaturation;
              if (reply.sample == sample.out &&
                  (reply.status & kCompared) == (sample.status & kCompared)) {
                return;
              }
              throw std::runtime_error(fmt::format(
                  "the board on {} was reset during the session, and replaying the {} samples "
                  "taken before gives OUT {} (STATUS 0x{:02X}) for the {}th, where it gave {} "
                  "(0x{:02X}): its filters cannot be rebuilt (another bitstream, or sw[0] moved?)",
                  port_.device(), taken_.size(), reply.sample, reply.status, i + 1, sample.out,
                  sample.status));
            },
            true);
  }
  flush();
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
  const auto now = std::chrono::steady_clock::now();
  // Rounded up: truncated, a timeout of 1 ms left 0 ms to wait after every send, and the link
  // sent again without reading until its retries ran out.
  const auto left = std::chrono::ceil<std::chrono::milliseconds>(deadline - now);
  if (now >= deadline) {
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
  if (reset_seen_ || false_frame_seen_) {
    const bool board_reset = reset_seen_;
    reset_seen_ = false;
    false_frame_seen_ = false;
    if (recovering_) throw ResetDuringRecovery{board_reset};
    recover_from_reset(board_reset);
    return;
  }
  while (!in_flight_.empty() && in_flight_.front().answered) {
    InFlight done = std::move(in_flight_.front());
    in_flight_.pop_front();
    if (done.replay) {
      ++counts_.replayed;
    } else if (!is_command(done.frame)) {
      ++counts_.exchanges;
      taken_.push_back({done.request.channel, done.request.sample, done.reply.sample,
                        done.reply.status});
    }
    done.on_reply(done.reply);
  }
}

// The first reply to a request in flight is its answer; any other is stray.
void BoardLink::take(const board::Reply& reply) {
  const auto match = std::find_if(in_flight_.begin(), in_flight_.end(), [&](const InFlight& f) {
    return f.request.seq == reply.seq && f.request.channel == reply.channel;
  });
  if (match == in_flight_.end() || match->answered) {
    // A windowed sample reply under the SEQ of a request still unanswered, for another CHANNEL:
    // the board took a damaged frame for that request and will drop the request itself (its SEQ
    // is answered) while it takes the ones after it. Replies come in the order of the frames, so
    // no earlier session's reply can come now. Recovered from as from a reset (pump).
    constexpr std::uint8_t kWindowedOnly = board::kStatusWindowed | board::kStatusSessionReset;
    const bool false_frame =
        (reply.status & kWindowedOnly) == board::kStatusWindowed &&
        std::any_of(in_flight_.begin(), in_flight_.end(), [&](const InFlight& f) {
          return !f.answered && !is_command(f.frame) && f.request.seq == reply.seq &&
                 f.request.channel != reply.channel;
        });
    if (false_frame) {
      false_frame_seen_ = true;
      return;
    }
    ++counts_.stray_replies;
    return;
  }
  // The session reset's answer has SESSION_RESET; another reply with SEQ 0 came from before it.
  if (is_command(match->frame) && !(reply.status & board::kStatusSessionReset)) {
    ++counts_.stray_replies;
    return;
  }
  // A board reset (btnC, power) ends the windowed session: the board answers as a plain one, its
  // filters from zero. Such a reply is never taken; the link recovers (pump).
  if (!(reply.status & board::kStatusWindowed)) {
    reset_seen_ = true;
    return;
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
