// SPDX-License-Identifier: MIT
// The Verilated board top behind a pseudo-terminal: the host code opens the pty's slave exactly as
// it opens /dev/ttyUSB1, and a thread moves the bytes between the pty's master and the board's
// RX/TX pins (bit by bit in the simulation). Header only: each test binary links its own board
// build (board_bench.h).
#pragma once

#include <fcntl.h>
#include <poll.h>
#include <termios.h>
#include <unistd.h>

#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "board_bench.h"

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

// The board behind the pty, in a thread. `mangle` may alter host -> board bytes (the n-th byte
// overall) to model a noisy cable: return false to drop the byte.
class PtyBoard {
 public:
  using Mangle = std::function<bool(std::uint64_t index, std::uint8_t& byte)>;
  explicit PtyBoard(const Pty& pty, Mangle mangle = {})
      : pty_(pty), mangle_(std::move(mangle)), thread_([this] { loop(); }) {}
  ~PtyBoard() {
    stop_ = true;
    thread_.join();
  }
  PtyBoard(const PtyBoard&) = delete;
  PtyBoard& operator=(const PtyBoard&) = delete;
  bool assertion_failed() const { return assertion_failed_; }

 private:
  void loop() {
    BoardBench bench;
    std::uint64_t index = 0;
    while (!stop_) {
      std::uint8_t buffer[256];
      const ssize_t n = ::read(pty_.master(), buffer, sizeof buffer);
      std::vector<std::uint8_t> bytes;
      for (ssize_t i = 0; i < n; ++i) {
        std::uint8_t byte = buffer[i];
        if (!mangle_ || mangle_(index, byte)) bytes.push_back(byte);
        ++index;
      }
      if (!bytes.empty()) bench.send(bytes);
      bench.run(std::uint64_t{32} * kSimClksPerBit);
      forward(bench);
      if (n <= 0 && !bench.sending()) {
        pollfd pfd{pty_.master(), POLLIN, 0};
        ::poll(&pfd, 1, 1);
      }
    }
    assertion_failed_ = bench.assertion_failed();
  }
  // The bytes the board sent, to the host.
  void forward(BoardBench& bench) {
    std::vector<std::uint8_t> reply;
    for (const TxByte& b : bench.received()) reply.push_back(b.value);
    bench.received().clear();
    std::size_t done = 0;
    while (done < reply.size() && !stop_) {
      const ssize_t w = ::write(pty_.master(), reply.data() + done, reply.size() - done);
      if (w > 0) done += static_cast<std::size_t>(w);
    }
  }

  const Pty& pty_;
  Mangle mangle_;
  std::atomic<bool> stop_{false};
  std::atomic<bool> assertion_failed_{false};
  std::thread thread_;
};

}  // namespace flange::tb::board
