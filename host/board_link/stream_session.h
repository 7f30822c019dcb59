// SPDX-License-Identifier: MIT
// Recordings through the Basys-3 board over its serial port (docs/board.md). Each row becomes a
// clearance (the calibration's regression, as `flange run` does, or the thesis's eq. 3.14), a
// Q1.15 word (sample_scaling.h) and one request frame with its channel (board_frame.h); the
// board's reply carries the filtered word. The session starts with a reset command: the board's
// filters start from zero history, as the model does in `flange run`. Stop-and-wait: a request is
// sent again (same SEQ) when its reply does not come within the timeout; the board answers a
// repeated SEQ without filtering it twice. Several recordings (one per channel, e.g. a
// locomotive's) go out interleaved in time order (channel_stream.h).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "board_link.h"
#include "channel_stream.h"

namespace flange::host {

struct StreamSettings {
  std::string port;         // serial device, e.g. /dev/ttyUSB1
  std::string input;        // recording CSV (t_s, clearance_mm, temp_c, voltage_v)
  std::string calibration;  // model.json from flange calibrate; empty: the thesis's eq. 3.14
  std::string out;          // output CSV
  int baud = 115200;        // the bitstream's: 100 MHz / ClksPerBit (docs/board.md)
  int timeout_ms = 500;     // per attempt, 1..60000
  int retries = 3;          // further attempts per sample before giving up, 0..100
  int window = 16;          // requests in flight, 1..kMaxWindow (board_link.h)
  // Gets one line on the port's latency setting (low_latency.h) once the port is open.
  std::function<void(const std::string&)> on_port_setup;
};

// One channel of a multichannel session: its recording and where its output goes.
struct ChannelFiles {
  int channel = 0;          // the board's channel, 0..255, each once
  std::string input;        // recording CSV (t_s, clearance_mm, temp_c, voltage_v)
  std::string out;          // output CSV, the columns of stream_recording's
  std::string calibration;  // this sensor's model.json; empty: the session's
};

struct ChannelStreamSettings {
  std::string port;                    // serial device, e.g. /dev/ttyUSB1
  std::vector<ChannelFiles> channels;  // at least one
  std::string calibration;             // model.json for channels without one; empty: eq. 3.14
  std::string coeffs;                  // the board's filter.json: check every reply; empty: don't
  std::string source;                  // what error lines name for the whole set (a manifest)
  LinkSettings link;
  // Gets one line on the port's latency setting (low_latency.h) once the port is open.
  std::function<void(const std::string&)> on_port_setup;
};

// One recording on channel 0. Checks the whole recording first (a bad row throws InputError
// before the board sees a sample), then streams it and writes the output CSV (t_s,
// clearance_raw_mm,word_in,word_out,clearance_filt_mm,status). Throws std::runtime_error when the
// port fails, the board does not answer or the output cannot be written (one line naming the
// port or file).
StreamCounts stream_recording(const StreamSettings& settings);

// Several recordings, one per channel, as one session: every file is checked first, then the rows
// go out in time order (t_s; ties in the order of `channels`) and each channel's replies go to its
// output CSV. With `coeffs`, every reply is checked against the model (mismatches are counted,
// the session goes on). Throws InputError for bad input (a bad row, a channel listed twice or
// outside the board's or the set's channels: one line naming the file or `source`),
// std::runtime_error as stream_recording.
StreamCounts stream_channel_recordings(const ChannelStreamSettings& settings);

}  // namespace flange::host
