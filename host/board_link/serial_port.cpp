// SPDX-License-Identifier: MIT
#include "serial_port.h"

#include "low_latency.h"

#include <fcntl.h>
#include <poll.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <iterator>
#include <stdexcept>

namespace flange::host {
namespace {

speed_t baud_constant(int baud) {
  // The termios constants of kSerialBauds, in the same order.
  static constexpr speed_t kConstants[] = {B9600,    B19200,   B38400,   B57600,
                                           B115200,  B230400,  B460800,  B921600,
                                           B1000000, B2000000, B3000000, B4000000};
  static_assert(std::size(kConstants) == std::size(kSerialBauds));
  for (std::size_t i = 0; i < std::size(kSerialBauds); ++i) {
    if (kSerialBauds[i] == baud) return kConstants[i];
  }
  throw std::runtime_error("unsupported baud rate " + std::to_string(baud));
}

std::runtime_error system_error(const std::string& what, const std::string& device) {
  return std::runtime_error(what + " " + device + ": " + std::strerror(errno));
}

}  // namespace

SerialPort::SerialPort(const std::string& device, int baud) : device_(device) {
  const speed_t speed = baud_constant(baud);
  fd_ = ::open(device.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd_ < 0) throw system_error("cannot open serial port", device);
  termios tio{};
  if (::tcgetattr(fd_, &tio) != 0) {
    const auto error = system_error("not a serial port (tcgetattr)", device);
    ::close(fd_);
    throw error;
  }
  ::cfmakeraw(&tio);
  tio.c_cflag &= ~static_cast<tcflag_t>(PARENB | CSTOPB | CSIZE | CRTSCTS);
  tio.c_cflag |= CS8 | CLOCAL | CREAD;
  tio.c_iflag &= ~static_cast<tcflag_t>(IXON | IXOFF | IXANY);
  tio.c_cc[VMIN] = 0;
  tio.c_cc[VTIME] = 0;
  if (::cfsetispeed(&tio, speed) != 0 || ::cfsetospeed(&tio, speed) != 0 ||
      ::tcsetattr(fd_, TCSANOW, &tio) != 0) {
    const auto error = system_error("cannot configure serial port", device);
    ::close(fd_);
    throw error;
  }
}

SerialPort::~SerialPort() {
  if (fd_ >= 0) ::close(fd_);
}

void SerialPort::write_all(std::span<const std::uint8_t> bytes, std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd_, bytes.data() + done, bytes.size() - done);
    if (n > 0) {
      done += static_cast<std::size_t>(n);
      continue;
    }
    if (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR) {
      throw system_error("cannot write to", device_);
    }
    const auto now = std::chrono::steady_clock::now();
    if (now >= deadline) throw std::runtime_error("timeout writing to " + device_);
    // Rounded up, as BoardLink's wait: truncated, a 1 ms timeout gave up at once.
    const auto left = std::chrono::ceil<std::chrono::milliseconds>(deadline - now);
    pollfd pfd{fd_, POLLOUT, 0};
    ::poll(&pfd, 1, static_cast<int>(left.count()));
  }
}

std::size_t SerialPort::read_some(std::span<std::uint8_t> buffer,
                                  std::chrono::milliseconds timeout) {
  pollfd pfd{fd_, POLLIN, 0};
  const int ready = ::poll(&pfd, 1, static_cast<int>(timeout.count()));
  if (ready < 0) {
    if (errno == EINTR) return 0;
    throw system_error("cannot wait for", device_);
  }
  if (ready == 0) return 0;
  const ssize_t n = ::read(fd_, buffer.data(), buffer.size());
  if (n < 0) {
    if (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR) return 0;
    if (errno == EIO) throw std::runtime_error("the other end of " + device_ + " hung up");
    throw system_error("cannot read from", device_);
  }
  if (n == 0 && (pfd.revents & POLLHUP)) {
    throw std::runtime_error("the other end of " + device_ + " hung up");
  }
  return static_cast<std::size_t>(n);
}

void SerialPort::discard_input() { ::tcflush(fd_, TCIFLUSH); }

std::string SerialPort::request_low_latency() { return host::request_low_latency(fd_, device_); }

}  // namespace flange::host
