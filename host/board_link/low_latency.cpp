// SPDX-License-Identifier: MIT
#include "low_latency.h"

#include <linux/serial.h>
#include <sys/ioctl.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <system_error>

namespace flange::host {
namespace {

// The sysfs latency timer of a USB-serial tty (empty when the device is none).
std::filesystem::path latency_timer_file(const std::string& device) {
  std::error_code ec;
  const std::filesystem::path real = std::filesystem::canonical(device, ec);
  if (ec) return {};
  const std::filesystem::path file =
      std::filesystem::path("/sys/bus/usb-serial/devices") / real.filename() / "latency_timer";
  return std::filesystem::exists(file, ec) ? file : std::filesystem::path{};
}

std::string read_line(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  return line;
}

// ASYNC_LOW_LATENCY through TIOCSSERIAL; "" when done, else why not.
std::string set_async_low_latency(int fd) {
  serial_struct serial{};
  if (::ioctl(fd, TIOCGSERIAL, &serial) != 0) {
    return std::string("TIOCGSERIAL: ") + std::strerror(errno);
  }
  serial.flags |= ASYNC_LOW_LATENCY;
  if (::ioctl(fd, TIOCSSERIAL, &serial) != 0) {
    return std::string("TIOCSSERIAL: ") + std::strerror(errno);
  }
  return "";
}

}  // namespace

std::string request_low_latency(int fd, const std::string& device) {
  const std::filesystem::path timer = latency_timer_file(device);
  const std::string ioctl_error = set_async_low_latency(fd);
  if (ioctl_error.empty()) {
    if (timer.empty()) return "low-latency mode (ASYNC_LOW_LATENCY) set on " + device;
    return "low-latency mode (ASYNC_LOW_LATENCY) set on " + device + ", FTDI latency timer " +
           read_line(timer) + " ms";
  }
  if (timer.empty()) {
    return "could not set low latency on " + device + " (" + ioctl_error +
           "; no FTDI latency timer in sysfs): replies may wait for the chip's timer";
  }
  std::ofstream out(timer);
  out << "1\n";
  out.close();
  if (out && read_line(timer) == "1") {
    return "FTDI latency timer of " + device + " set to 1 ms through " + timer.string();
  }
  return "could not set low latency on " + device + " (" + ioctl_error + "; " + timer.string() +
         " not writable): replies wait up to its " + read_line(timer) + " ms";
}

}  // namespace flange::host
