// SPDX-License-Identifier: MIT
// A serial port in raw 8N1 mode through termios: the host side of the Basys-3 USB-UART (and of a
// pseudo-terminal in the tests, so that both run this same code).
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

namespace flange::host {

class SerialPort {
 public:
  // Opens `device` (e.g. /dev/ttyUSB1) raw, 8N1, no flow control, at `baud` (one of the standard
  // rates 9600..921600). Throws std::runtime_error naming the device and the system error.
  SerialPort(const std::string& device, int baud);
  ~SerialPort();
  SerialPort(const SerialPort&) = delete;
  SerialPort& operator=(const SerialPort&) = delete;

  // Writes every byte (waits at most `timeout` in total; throws on an error or timeout).
  void write_all(std::span<const std::uint8_t> bytes, std::chrono::milliseconds timeout);
  // Reads what is there, waiting at most `timeout` for the first byte; 0 bytes on a timeout.
  std::size_t read_some(std::span<std::uint8_t> buffer, std::chrono::milliseconds timeout);
  // Drops bytes received but not read (stale replies of an earlier session).
  void discard_input();
  const std::string& device() const { return device_; }

 private:
  std::string device_;
  int fd_ = -1;
};

}  // namespace flange::host
