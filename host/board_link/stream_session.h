// SPDX-License-Identifier: MIT
// A recording through the Basys-3 board over its serial port (docs/board.md). Each row becomes a
// clearance (the calibration's regression, as `flange run` does, or the thesis's eq. 3.14), a
// Q1.15 word (sample_scaling.h) and one request frame (board_frame.h); the board's reply carries
// the filtered word. The session starts with a reset command: the board's filter starts from
// zero history, as the model does in `flange run`. Stop-and-wait: a request is sent again (same
// SEQ) when its reply does not come within the timeout; the board answers a repeated SEQ without
// filtering it twice.
#pragma once

#include <cstdint>
#include <string>

namespace flange::host {

struct StreamSettings {
  std::string port;         // serial device, e.g. /dev/ttyUSB1
  std::string input;        // recording CSV (t_s, clearance_mm, temp_c, voltage_v)
  std::string calibration;  // model.json from flange calibrate; empty: the thesis's eq. 3.14
  std::string out;          // output CSV
  int baud = 115200;        // the board's ClksPerBit: 100 MHz / 868
  int timeout_ms = 500;     // per attempt, 1..60000
  int retries = 3;          // further attempts per sample before giving up, 0..100
};

struct StreamCounts {
  std::uint64_t samples = 0;
  std::uint64_t resent = 0;          // requests sent again after a timeout
  std::uint64_t stray_replies = 0;   // intact replies with another SEQ (late or stale)
  std::uint64_t link_errors = 0;     // replies whose STATUS reports discarded bytes
  std::uint64_t overruns = 0;        // replies whose STATUS reports a dropped frame
  std::uint64_t saturated = 0;       // replies whose STATUS reports clipping
  std::uint64_t bypassed = 0;        // replies with the unfiltered input (sw[0] up)
  std::uint64_t clipped_inputs = 0;  // clearances outside the sample word's range
  std::uint64_t discarded_bytes = 0;
  double seconds = 0.0;  // wall time of the session
};

// Checks the whole recording first (a bad row throws InputError before the board sees a sample),
// then streams it and writes the output CSV (t_s,clearance_raw_mm,word_in,word_out,
// clearance_filt_mm,status). Throws std::runtime_error when the port fails, the board does not
// answer or the output cannot be written (one line naming the port or file).
StreamCounts stream_recording(const StreamSettings& settings);

// The one-line summary `flange stream` prints.
std::string stream_summary_line(const StreamCounts& counts);

}  // namespace flange::host
