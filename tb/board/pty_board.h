// SPDX-License-Identifier: MIT
// The Verilated board top behind a pseudo-terminal: the host code opens the pty's slave exactly as
// it opens /dev/ttyUSB1, and a thread moves the bytes between the pty's master and the board's
// RX/TX pins (bit by bit in the simulation), at once or through an FTDI chip's timing
// (ftdi_link.h). Header only: each test binary links its own board
// build (board_bench.h).
#pragma once

#include <fcntl.h>
#include <fmt/format.h>
#include <poll.h>
#include <termios.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "basys3_top_model.h"
#include "board_bench.h"
#include "board_frame.h"
#include "filter_json.h"
#include "ftdi_link.h"

namespace flange::tb::board {

// A pseudo-terminal; the slave stays open (raw) for the object's lifetime so that the master never
// sees a hang-up between the host code's open and close.
class Pty {
 public:
  Pty() {
    master_ = ::posix_openpt(O_RDWR | O_NOCTTY);
    if (master_ < 0 || ::grantpt(master_) != 0 || ::unlockpt(master_) != 0) {
      throw std::runtime_error("posix_openpt failed");
    }
    slave_name_ = ::ptsname(master_);
    slave_ = ::open(slave_name_.c_str(), O_RDWR | O_NOCTTY);
    termios tio{};
    ::tcgetattr(slave_, &tio);
    ::cfmakeraw(&tio);
    ::tcsetattr(slave_, TCSANOW, &tio);
    ::fcntl(master_, F_SETFL, O_NONBLOCK);
  }
  ~Pty() {
    ::close(slave_);
    ::close(master_);
  }
  Pty(const Pty&) = delete;
  Pty& operator=(const Pty&) = delete;
  int master() const { return master_; }
  const std::string& slave_name() const { return slave_name_; }

 private:
  int master_ = -1, slave_ = -1;
  std::string slave_name_;
};

// What sits between the pty and the board: a noisy cable, an FTDI chip's timing, a reset.
struct PtyBoardOptions {
  using Mangle = std::function<bool(std::uint64_t index, std::uint8_t& byte)>;
  // Alters host -> board bytes (the n-th byte overall) to model a noisy cable: return false to
  // drop the byte.
  Mangle mangle;
  // The same for board -> host bytes (the n-th byte the board sent).
  Mangle mangle_reply;
  // With settings, the bytes go through an FTDI chip's timing (ftdi_link.h); without, at once.
  std::optional<FtdiSettings> ftdi;
  // btnC is pressed just before each host -> board byte with one of these indices reaches the
  // board.
  std::vector<std::uint64_t> reset_before_bytes;
  // btnC is also pressed before a host -> board byte when this returns true, given the frame's
  // worth of bytes that reached the board before it: a reset placed by content.
  std::function<bool(std::span<const std::uint8_t> before, std::uint8_t byte)> reset_when;
  // The protocol model (basys3_top_model.h) instead of the Verilated top: as fast as the link
  // it is given, where the Verilated top is slower than a real 921600-baud wire.
  bool protocol_model = false;
  // With the FTDI chip: after each btnC, and after the first windowed session reset that reaches
  // the board at the start and after each btnC (not its copies the host sends again), the chip
  // holds the board's replies this long (FtdiLink::hold_until). Longer than the host's timeout,
  // it makes the host send the session reset, and the requests in flight, again before their
  // replies come, whatever the machine's load (docs/board.md, "Recovery under stress").
  std::chrono::milliseconds hold_replies{0};
};

// The board behind the pty, in a thread.
class PtyBoard {
 public:
  using Mangle = PtyBoardOptions::Mangle;
  using Clock = FtdiLink::Clock;
  explicit PtyBoard(const Pty& pty, Mangle mangle = {})
      : PtyBoard(pty.master(), PtyBoardOptions{std::move(mangle), {}, {}, {}, {}, false}) {}
  PtyBoard(const Pty& pty, PtyBoardOptions options) : PtyBoard(pty.master(), std::move(options)) {}
  // `fd`: the board's end of the connection, non-blocking (a pty's master, a socket pair's end:
  // socket_stream.h).
  PtyBoard(int fd, PtyBoardOptions options)
      : fd_(fd), options_(std::move(options)), thread_([this] { loop(); }) {}
  ~PtyBoard() { stop(); }
  PtyBoard(const PtyBoard&) = delete;
  PtyBoard& operator=(const PtyBoard&) = delete;
  bool assertion_failed() const { return assertion_failed_; }
  int resets() const { return resets_; }
  // Stops the board's thread (the destructor does it too); then trace() may be read.
  void stop() {
    stop_ = true;
    if (thread_.joinable()) thread_.join();
  }
  // Every byte the board took and sent and every btnC, with the time since the board started, a
  // line per run of bytes one way (the Verilated top only): what a failed session is replayed
  // from, through the protocol model, to find its cause. Empty until stop().
  std::string trace() const {
    if (thread_.joinable()) return {};
    std::string out;
    char kind = 0;
    for (const TraceEvent& e : trace_) {
      if (e.kind != kind || e.kind == 'R') {
        out += fmt::format("{}{:.3f} ms {}", out.empty() ? "" : "\n", static_cast<double>(e.micros) / 1000.0,
                           e.kind == 'R' ? "btnC" : e.kind == 'T' ? "to board:" : "from board:");
        kind = e.kind;
      }
      if (e.kind != 'R') out += fmt::format(" {:02X}", e.byte);
    }
    return out;
  }

 private:
  // The board runs while it has bytes to take or has sent one within this many bit times (its
  // queue of frames keeps it answering long after the last request came in).
  static constexpr int kQuietBits = 200;

  void loop() {
    if (options_.protocol_model) {
      model_loop();
      return;
    }
    BoardBench bench;
    std::optional<FtdiLink> ftdi;
    if (options_.ftdi) ftdi.emplace(*options_.ftdi, Clock::now());
    std::uint64_t quiet_cycles = 0;
    while (!stop_) {
      std::vector<std::uint8_t> to_board = from_host();
      if (ftdi) {
        ftdi->from_host(to_board, Clock::now());
        to_board = ftdi->to_board(Clock::now());
      }
      if (!to_board.empty()) {
        feed(bench, to_board, ftdi ? &*ftdi : nullptr);
        quiet_cycles = 0;
      }
      const bool active =
          bench.sending() || quiet_cycles < std::uint64_t{kQuietBits} * kSimClksPerBit;
      if (active) {
        constexpr std::uint64_t kChunk = std::uint64_t{32} * kSimClksPerBit;
        bench.run(kChunk);
        quiet_cycles += kChunk;
      }
      std::vector<std::uint8_t> sent = mangled_reply(from_board(bench));
      for (std::uint8_t byte : sent) record('F', byte);
      if (!sent.empty()) quiet_cycles = 0;
      if (ftdi) {
        ftdi->from_board(sent, Clock::now());
        sent = ftdi->to_host(Clock::now());
      }
      to_host(sent);
      if (!active)
        wait(ftdi ? ftdi->next_event(Clock::now() + kIdlePoll) : Clock::now() + kIdlePoll);
    }
    assertion_failed_ = bench.assertion_failed();
  }
  static constexpr std::chrono::milliseconds kIdlePoll{1};

  // The same with the protocol model: each byte is answered at once, the FTDI link times it.
  void model_loop() {
    Basys3TopModel board(model::load_core_config(kBoardFilterJson));
    std::optional<FtdiLink> ftdi;
    if (options_.ftdi) ftdi.emplace(*options_.ftdi, Clock::now());
    while (!stop_) {
      std::vector<std::uint8_t> to_board = from_host();
      if (ftdi) {
        ftdi->from_host(to_board, Clock::now());
        to_board = ftdi->to_board(Clock::now());
      }
      std::vector<std::uint8_t> sent;
      for (std::uint8_t byte : to_board) {
        const std::vector<std::uint8_t> reply = board.take(byte);
        sent.insert(sent.end(), reply.begin(), reply.end());
      }
      sent = mangled_reply(sent);
      if (ftdi) {
        ftdi->from_board(sent, Clock::now());
        sent = ftdi->to_host(Clock::now());
      }
      to_host(sent);
      wait(ftdi ? ftdi->next_event(Clock::now() + kIdlePoll) : Clock::now() + kIdlePoll);
    }
  }

  // The host's bytes (through the noisy cable).
  std::vector<std::uint8_t> from_host() {
    std::uint8_t buffer[256];
    const ssize_t n = ::read(fd_, buffer, sizeof buffer);
    std::vector<std::uint8_t> bytes;
    for (ssize_t i = 0; i < n; ++i) {
      std::uint8_t byte = buffer[i];
      if (!options_.mangle || options_.mangle(host_index_, byte)) bytes.emplace_back(byte);
      ++host_index_;
    }
    return bytes;
  }
  // Onto the RX pin; btnC first when the reset byte is among them. The chip holds the replies
  // after a btnC or a windowed session reset when asked to.
  void feed(BoardBench& bench, const std::vector<std::uint8_t>& bytes, FtdiLink* ftdi) {
    for (std::uint8_t byte : bytes) {
      const bool hold = ftdi && options_.hold_replies.count() > 0;
      if (std::find(options_.reset_before_bytes.begin(), options_.reset_before_bytes.end(),
                    fed_index_) != options_.reset_before_bytes.end() ||
          (options_.reset_when && options_.reset_when(last_fed_, byte))) {
        bench.drain();
        bench.press_reset();
        ++resets_;
        record('R', 0);
        if (hold) ftdi->hold_until(Clock::now() + options_.hold_replies);
        hold_armed_ = true;
      }
      bench.send({byte});
      record('T', byte);
      ++fed_index_;
      std::copy(last_fed_.begin() + 1, last_fed_.end(), last_fed_.begin());
      last_fed_.back() = byte;
      if (hold && hold_armed_ && is_windowed_session_reset(last_fed_)) {
        ftdi->hold_until(Clock::now() + options_.hold_replies);
        hold_armed_ = false;
      }
    }
  }
  static bool is_windowed_session_reset(
      const std::array<std::uint8_t, host::board::kRequestBytes>& frame) {
    namespace f = host::board;
    return frame[0] == f::kCommandSync && frame[3] == 0 && frame[4] == f::kCommandResetWindowed &&
           f::crc8(std::span<const std::uint8_t>(frame).subspan(1, 4)) == frame[5];
  }
  // The bytes the board sent.
  static std::vector<std::uint8_t> from_board(BoardBench& bench) {
    std::vector<std::uint8_t> bytes;
    for (const TxByte& b : bench.received()) bytes.push_back(b.value);
    bench.received().clear();
    return bytes;
  }
  // Through the noisy cable back.
  std::vector<std::uint8_t> mangled_reply(const std::vector<std::uint8_t>& sent) {
    std::vector<std::uint8_t> bytes;
    for (std::uint8_t byte : sent) {
      if (!options_.mangle_reply || options_.mangle_reply(board_index_, byte)) {
        bytes.push_back(byte);
      }
      ++board_index_;
    }
    return bytes;
  }
  void to_host(const std::vector<std::uint8_t>& bytes) {
    std::size_t done = 0;
    while (done < bytes.size() && !stop_) {
      const ssize_t w = ::write(fd_, bytes.data() + done, bytes.size() - done);
      if (w > 0) done += static_cast<std::size_t>(w);
    }
  }
  // Sleeps until `until` or a byte from the host.
  void wait(Clock::time_point until) const {
    const auto left = std::chrono::duration_cast<std::chrono::nanoseconds>(until - Clock::now());
    if (left.count() <= 0) return;
    const timespec ts{static_cast<time_t>(left.count() / 1'000'000'000),
                      static_cast<long>(left.count() % 1'000'000'000)};
    pollfd pfd{fd_, POLLIN, 0};
    ::ppoll(&pfd, 1, &ts, nullptr);
  }

  struct TraceEvent {
    char kind;  // 'T': to the board, 'F': from it, 'R': btnC
    std::uint8_t byte;
    std::int64_t micros;
  };
  void record(char kind, std::uint8_t byte) {
    const auto since = std::chrono::duration_cast<std::chrono::microseconds>(
        Clock::now() - trace_start_);
    trace_.push_back({kind, byte, since.count()});
  }

  int fd_;
  PtyBoardOptions options_;
  Clock::time_point trace_start_ = Clock::now();
  std::vector<TraceEvent> trace_;  // written by the board's thread only
  std::uint64_t host_index_ = 0, fed_index_ = 0, board_index_ = 0;
  std::array<std::uint8_t, host::board::kRequestBytes> last_fed_{};  // the last frame's worth
  bool hold_armed_ = true;  // the next windowed session reset starts a hold
  std::atomic<bool> stop_{false};
  std::atomic<bool> assertion_failed_{false};
  std::atomic<int> resets_{0};
  std::thread thread_;
};

}  // namespace flange::tb::board
