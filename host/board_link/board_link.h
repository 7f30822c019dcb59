// SPDX-License-Identifier: MIT
// A window of requests in flight over the Basys-3 link (docs/board.md, "Windowed session"): SEQ
// numbering, the windowed session reset that starts every session and reports how many channels
// the board's core serves, up to `window` requests sent before their replies come, replies handed
// back in the order the requests were made, and go-back-N on a timeout: every request still
// unanswered is sent again (same SEQ, same CHANNEL). The board takes new frames only in SEQ order
// and answers a repeated one from its reply store, so every sample is filtered exactly once and
// in order, whatever is lost or damaged on the way. A board reset during the session (btnC, power)
// is recovered from: the link restarts the windowed session and replays every sample it has
// taken since the session began, so each channel's filter is back where it was, bit for bit,
// before the requests still unanswered go again.
#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <deque>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "board_frame.h"
#include "byte_stream.h"

namespace flange::host {

// The board's frame queue and reply store: the largest window (rtl/board/basys3_top.sv).
inline constexpr int kMaxWindow = 32;
// Board resets one session recovers from before it gives up (each costs a replay of the session).
inline constexpr int kMostBoardResets = 8;

struct LinkSettings {
  int baud = 115200;     // the bitstream's: 100 MHz / ClksPerBit (docs/board.md, "Link budget")
  int timeout_ms = 500;  // for the oldest request in flight, 1..60000
  int retries = 3;       // further attempts per request before giving up, 0..100
  int window = 16;       // requests in flight, 1..kMaxWindow (1: stop-and-wait)
};

struct LinkCounts {
  std::uint64_t exchanges = 0;        // sample requests answered
  std::uint64_t resent = 0;           // requests sent again after a timeout
  std::uint64_t stray_replies = 0;    // intact replies to no request in flight (late or repeated)
  std::uint64_t discarded_bytes = 0;  // received bytes that were part of no intact reply
  std::uint64_t board_resets = 0;     // resets of the board during the session, recovered from
  std::uint64_t replayed = 0;         // samples sent again after a reset to rebuild the filters
  // Damaged requests the board took for valid ones under the SEQ of a request in flight (a lost
  // byte and the next SYNC can pass the CRC-8), recovered from as from a reset.
  std::uint64_t false_frames = 0;
};

class BoardLink {
 public:
  using OnReply = std::function<void(const board::Reply&)>;

  // `port` must outlive the link. Throws std::invalid_argument for a window outside 1..32.
  BoardLink(ByteStream& port, const LinkSettings& settings);

  // Waits for the requests in flight, then restarts the session with SEQ 0 as a windowed one: the
  // board resets every channel's filter and forgets its stored replies. Returns the number of
  // channels of the board's core (1..255). Throws std::runtime_error when the board does not
  // answer or does not confirm a windowed reset.
  int reset_session();

  // Sends `word` on `channel` (0..255) with the next SEQ, after waiting while `window` requests
  // are in flight; `on_reply` gets its reply, and replies are handed on in the order of post().
  // Throws std::runtime_error naming the port when the oldest request stays unanswered after
  // retries + 1 attempts (`what` names it, e.g. "sample 17 of channel 3"), when the board was
  // reset more than kMostBoardResets times, or when a replay after a reset does not give the
  // replies the board gave before it.
  void post(std::uint8_t channel, std::int16_t word, std::string what, OnReply on_reply);
  // Waits until every request in flight is answered (throws as post()).
  void flush();
  // One request and its reply (post, then flush).
  board::Reply exchange(std::uint8_t channel, std::int16_t word, const std::string& what);

  const LinkCounts& counts() const { return counts_; }
  const std::string& device() const { return port_.device(); }
  int window() const { return settings_.window; }

 private:
  struct InFlight {
    InFlight(const board::Request& r, const std::array<std::uint8_t, board::kRequestBytes>& f,
             std::string w, OnReply done)
        : request(r), frame(f), what(std::move(w)), on_reply(std::move(done)) {}
    board::Request request;
    std::array<std::uint8_t, board::kRequestBytes> frame;  // as sent: a sample or a command
    std::string what;
    OnReply on_reply;
    bool replay = false;  // a sample sent again after a board reset: checked, not handed on
    bool answered = false;
    board::Reply reply;
    int attempts = 1;  // sends while it was the oldest request in flight
    std::chrono::steady_clock::time_point sent;
  };

  // Reads replies until the oldest request in flight is answered or times out (then resends).
  void pump();
  void take(const board::Reply& reply);
  void resend_unanswered();
  void send(InFlight& request);
  // The windowed session reset (SEQ 0); returns the board's channel count.
  int restart_board();
  // post(), or a replay's request (checked by `on_reply`, not taken again) when `replay`.
  void enqueue(std::uint8_t channel, std::int16_t word, std::string what, OnReply on_reply,
               bool replay);
  void replay_taken();
  // After replies showed a board reset (`board_reset`) or a false frame: restart the session,
  // replay every sample taken, then send the requests that were in flight again, in order, with
  // new SEQs.
  void recover_from_reset(bool board_reset);

  ByteStream& port_;
  LinkSettings settings_;
  board::ReplyScanner scanner_;
  LinkCounts counts_;
  std::deque<InFlight> in_flight_;
  std::uint8_t next_seq_ = 1;
  // The samples taken since the session began, with their replies: what a replay after a board
  // reset sends again (8 bytes a sample: 35 MB for an hour of 12 wheels at 100 Hz).
  struct TakenSample {
    std::uint8_t channel = 0;
    std::int16_t word = 0;
    std::int16_t out = 0;
    std::uint8_t status = 0;
  };
  std::vector<TakenSample> taken_;
  int board_channels_ = 0;
  bool reset_seen_ = false;        // a reply to a request in flight was not of a windowed session
  bool false_frame_seen_ = false;  // a reply under a request's SEQ names another CHANNEL
  bool recovering_ = false;
};

}  // namespace flange::host
