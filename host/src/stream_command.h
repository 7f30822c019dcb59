// SPDX-License-Identifier: MIT
// `flange stream`: a recording through the Basys-3 board over its serial port. Each row becomes a
// clearance (the calibration's regression, as `flange run` does), a Q1.15 word
// (sample_scaling.h), one request frame; the board's reply carries the filtered word
// (docs/board.md). The session starts with a reset command: the board's filter starts from zero
// history, as the model does in `flange run`. Stop-and-wait: a request is sent again (same SEQ)
// when its reply does not come within the timeout; the board answers a repeated SEQ without
// filtering it twice.
#pragma once

#include <CLI/CLI.hpp>
#include <iosfwd>
#include <string>

namespace flange::host {

struct StreamOptions {
  std::string port;         // serial device, e.g. /dev/ttyUSB1
  std::string input;        // recording CSV (t_s, clearance_mm, temp_c, voltage_v)
  std::string calibration;  // model.json from flange calibrate; empty: the thesis's eq. 3.14
  std::string out;          // output CSV
  int baud = 115200;        // the board's ClksPerBit: 100 MHz / 868
  int timeout_ms = 500;     // per attempt, 1..60000
  int retries = 3;          // further attempts per sample before giving up, 0..100
};

CLI::App* add_stream_command(CLI::App& app, StreamOptions& options);

// Returns 0; 1 when the board does not answer or the port fails (one line naming the port);
// 2 for bad input (file, line, column).
int run_stream_command(const StreamOptions& options, std::ostream& out, std::ostream& err);

}  // namespace flange::host
