// SPDX-License-Identifier: MIT
// A serial port in raw 8N1 mode through termios: the host side of the Basys-3 USB-UART (and of a
// pseudo-terminal in the tests, so that both run this same code).
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

#include "byte_stream.h"

namespace flange::host {

// The baud rates a SerialPort opens (termios constants; the Basys-3's FT2232HQ does all of them).
// The board's rate is its bitstream's ClksPerBit: 100 MHz / baud (docs/board.md, "Link budget").
inline constexpr int kSerialBauds[] = {9600,   19200,  38400,   57600,   115200,  230400,
                                       460800, 921600, 1000000, 2000000, 3000000, 4000000};

class SerialPort : public ByteStream {
 public:
  // Opens `device` (e.g. /dev/ttyUSB1) raw, 8N1, no flow control, at `baud` (one of
  // kSerialBauds). Throws std::runtime_error naming the device and the system error.
  SerialPort(const std::string& device, int baud);
  ~SerialPort() override;
  SerialPort(const SerialPort&) = delete;
  SerialPort& operator=(const SerialPort&) = delete;

  // Writes every byte (waits at most `timeout` in total; throws on an error or timeout).
  void write_all(std::span<const std::uint8_t> bytes, std::chrono::milliseconds timeout) override;
  // Reads what is there, waiting at most `timeout` for the first byte; 0 bytes on a timeout.
  std::size_t read_some(std::span<std::uint8_t> buffer, std::chrono::milliseconds timeout) override;
  // Drops bytes received but not read (stale replies of an earlier session).
  void discard_input();
  // Asks for the port's low-latency mode or a 1 ms FTDI latency timer (low_latency.h); one line
  // saying which it set. The port works either way.
  std::string request_low_latency();
  const std::string& device() const override { return device_; }

 private:
  std::string device_;
  int fd_ = -1;
};

}  // namespace flange::host
