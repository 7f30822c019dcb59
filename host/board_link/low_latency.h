// SPDX-License-Identifier: MIT
// Makes a USB-serial port hand received bytes on at once, as a windowed session wants
// (docs/board.md, "Windowed session"): the port's low-latency mode (TIOCSSERIAL with
// ASYNC_LOW_LATENCY, which the Linux FTDI driver turns into a 1 ms latency timer), else the FTDI
// latency timer through sysfs
// (/sys/bus/usb-serial/devices/<tty>/latency_timer, usually root's to write). Neither is needed
// for the link to work: without them the chip holds replies up to its timer (16 ms by default).
#pragma once

#include <string>

namespace flange::host {

// Tries both on the open port `fd` of `device`; returns one line saying which it set (or that it
// could set neither, and why). Never throws.
std::string request_low_latency(int fd, const std::string& device);

}  // namespace flange::host
