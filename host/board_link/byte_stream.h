// SPDX-License-Identifier: MIT
// What BoardLink needs of a connection to the board: write bytes, read what is there, a name for
// messages. SerialPort is the real one (and a pseudo-terminal's, in the tests); the link
// benchmark connects through a socket pair (tb/board/socket_stream.h), whose wake-ups, unlike a
// pseudo-terminal's, do not wait for the kernel's work queue on a loaded machine.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

namespace flange::host {

class ByteStream {
 public:
  virtual ~ByteStream() = default;
  // Writes every byte (waits at most `timeout` in total; throws on an error or timeout).
  virtual void write_all(std::span<const std::uint8_t> bytes,
                         std::chrono::milliseconds timeout) = 0;
  // Reads what is there, waiting at most `timeout` for the first byte; 0 bytes on a timeout.
  virtual std::size_t read_some(std::span<std::uint8_t> buffer,
                                std::chrono::milliseconds timeout) = 0;
  virtual const std::string& device() const = 0;
};

}  // namespace flange::host
