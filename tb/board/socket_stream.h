// SPDX-License-Identifier: MIT
// A socket pair in place of a pseudo-terminal between the host code and the simulated board
// (pty_board.h): the host end is a host::ByteStream for BoardLink, the other end the board's.
// A pseudo-terminal hands bytes over through the kernel's work queue, which on a loaded shared
// machine adds waits of tens of milliseconds (measured: 99th percentile of a pty round trip
// 57 ms at load 17, of a socket pair's 18 us); the throughput tests and bench/link_bench.sh use
// this so that their figures are the simulated link's, not the machine's. Header only.
#pragma once

#include <fcntl.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>

#include "byte_stream.h"

namespace flange::tb::board {

class SocketStream : public host::ByteStream {
 public:
  SocketStream() {
    int fds[2];
    if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, fds) != 0) {
      throw std::runtime_error("socketpair failed");
    }
    host_ = fds[0];
    board_ = fds[1];
    ::fcntl(board_, F_SETFL, O_NONBLOCK);
  }
  ~SocketStream() override {
    ::close(host_);
    ::close(board_);
  }
  SocketStream(const SocketStream&) = delete;
  SocketStream& operator=(const SocketStream&) = delete;

  // The board's end, for PtyBoard.
  int board_end() const { return board_; }

  void write_all(std::span<const std::uint8_t> bytes, std::chrono::milliseconds) override {
    std::size_t done = 0;
    while (done < bytes.size()) {
      const ssize_t n = ::write(host_, bytes.data() + done, bytes.size() - done);
      if (n < 0 && errno != EINTR) throw std::runtime_error("cannot write to the socket pair");
      if (n > 0) done += static_cast<std::size_t>(n);
    }
  }
  std::size_t read_some(std::span<std::uint8_t> buffer,
                        std::chrono::milliseconds timeout) override {
    pollfd pfd{host_, POLLIN, 0};
    if (::poll(&pfd, 1, static_cast<int>(timeout.count())) <= 0) return 0;
    const ssize_t n = ::read(host_, buffer.data(), buffer.size());
    return n > 0 ? static_cast<std::size_t>(n) : 0;
  }
  const std::string& device() const override { return name_; }

 private:
  int host_ = -1, board_ = -1;
  std::string name_ = "the socket pair";
};

}  // namespace flange::tb::board
