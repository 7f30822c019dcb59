// SPDX-License-Identifier: MIT
// A host::ByteStream straight to a simulated board, run in the host's own thread: the board's
// protocol model (basys3_top_model.h) or the Verilated top at its pins (board_bench.h). Every
// frame the host writes reaches the board byte by byte through a hook that may pass, drop or
// alter a byte or press btnC before it; the board answers when the host reads (the Verilated top
// takes the bytes back to back, its frame queue filling as on the wire). So which byte is
// damaged and where btnC falls are fixed by the frames' content, not by the machine's
// scheduling, and a board that stops answering shows at once: a read with nothing to read waits
// out the host's timeout, as nothing can come later. Optionally the first read after each btnC
// and the first windowed session reset after it (and at the start) gets nothing (the replies come with the next one), so the host
// sends again before the board's answers come, as a USB stack that stops polling does.
// Header only; tb/board/board_link_damage_test.cpp sweeps damage over every SEQ with it.
#pragma once

#include <chrono>
#include <cstdint>
#include <deque>
#include <functional>
#include <span>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "basys3_top_model.h"
#include "board_bench.h"
#include "board_frame.h"
#include "byte_stream.h"

namespace flange::tb::board {

// What happens to one byte the host wrote.
enum class OnTheWire { kPass, kDrop, kResetBefore };

// The protocol model as a board of DirectStream.
class ModelBoard {
 public:
  explicit ModelBoard(const model::CoreConfig& config) : board_(config) {}
  void send(std::uint8_t byte) {
    const std::vector<std::uint8_t> reply = board_.take(byte);
    replies_.insert(replies_.end(), reply.begin(), reply.end());
  }
  void press_reset() { board_.press_reset(); }
  std::vector<std::uint8_t> replies() { return std::exchange(replies_, {}); }

 private:
  Basys3TopModel board_;
  std::vector<std::uint8_t> replies_;
};

// The Verilated top as a board of DirectStream: bytes queue on the RX pin and run when the host
// reads; btnC once the board has answered what came before it (as PtyBoard presses it).
class RtlBoard {
 public:
  explicit RtlBoard(const model::CoreConfig&) {}
  void send(std::uint8_t byte) { bench_.send({byte}); }
  void press_reset() {
    bench_.drain();
    bench_.press_reset();
  }
  std::vector<std::uint8_t> replies() {
    if (cycles_per_read_ > 0) {
      while (bench_.sending()) bench_.tick();
      bench_.run(cycles_per_read_);
    } else {
      bench_.drain();
    }
    std::vector<std::uint8_t> bytes;
    for (const TxByte& b : bench_.received()) bytes.push_back(b.value);
    bench_.received().clear();
    return bytes;
  }
  bool assertion_failed() const { return bench_.assertion_failed(); }
  // Replies slower than the host: each read runs the top until it has taken every byte written,
  // then this many cycles more (0: until it has answered everything), so that the host's timeout
  // can fire while frames wait in the board's queue.
  void set_cycles_per_read(std::uint64_t cycles) { cycles_per_read_ = cycles; }

 private:
  BoardBench bench_;
  std::uint64_t cycles_per_read_ = 0;
};

template <class Board>
class DirectStream : public host::ByteStream {
 public:
  // `frame`: the host's write (one request or command), `at`: the byte's place in it; the hook
  // may change `byte`. Called for every byte, in order.
  using Hook = std::function<OnTheWire(std::span<const std::uint8_t> frame, std::size_t at,
                                       std::uint8_t& byte)>;

  DirectStream(const model::CoreConfig& config, Hook hook, bool hold_after_resets)
      : board_(config), hook_(std::move(hook)), hold_after_resets_(hold_after_resets) {}

  void write_all(std::span<const std::uint8_t> bytes, std::chrono::milliseconds) override {
    namespace f = host::board;
    for (std::size_t at = 0; at < bytes.size(); ++at) {
      std::uint8_t byte = bytes[at];
      const OnTheWire what = hook_ ? hook_(bytes, at, byte) : OnTheWire::kPass;
      if (what == OnTheWire::kDrop) continue;
      if (what == OnTheWire::kResetBefore) {
        board_.press_reset();
        ++resets_;
        hold_ = hold_after_resets_;
        hold_armed_ = true;
      }
      board_.send(byte);
    }
    // The first copy of the session reset after power-up or btnC, not the copies sent again.
    if (hold_armed_ && bytes.size() == f::kRequestBytes && bytes[0] == f::kCommandSync &&
        bytes[4] == f::kCommandResetWindowed) {
      hold_ = hold_after_resets_;
      hold_armed_ = false;
    }
  }
  std::size_t read_some(std::span<std::uint8_t> buffer,
                        std::chrono::milliseconds timeout) override {
    const std::vector<std::uint8_t> more = board_.replies();
    replies_.insert(replies_.end(), more.begin(), more.end());
    if (replies_.empty() || hold_) {
      hold_ = false;
      std::this_thread::sleep_for(timeout);
      return 0;
    }
    std::size_t n = 0;
    for (; n < buffer.size() && !replies_.empty(); ++n) {
      buffer[n] = replies_.front();
      replies_.pop_front();
    }
    return n;
  }
  const std::string& device() const override { return name_; }

  int resets() const { return resets_; }
  Board& board() { return board_; }

 private:
  Board board_;
  Hook hook_;
  bool hold_after_resets_;
  bool hold_ = false;        // the next read gets nothing
  bool hold_armed_ = true;   // the next windowed session reset starts a hold
  std::deque<std::uint8_t> replies_;
  int resets_ = 0;
  std::string name_ = "the simulated board";
};

}  // namespace flange::tb::board
