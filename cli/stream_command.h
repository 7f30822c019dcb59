// SPDX-License-Identifier: MIT
// `flange stream`: the command line of host/board_link (a recording through the Basys-3 board's
// filter over its serial port, framed, checked and resent on timeout).
#pragma once

#include <CLI/CLI.hpp>
#include <iosfwd>

#include "stream_session.h"

namespace flange::cli {

// One recording (--input) on channel 0, or every channel of a locomotive manifest (--manifest),
// each on its own channel of the board's core.
struct StreamOptions {
  host::StreamSettings single;  // port, input, calibration, out and link settings
  std::string manifest;         // locomotive.json; then --out is a folder
  std::string coeffs;           // the board's filter.json: check every reply (manifest only)
};

CLI::App* add_stream_command(CLI::App& app, StreamOptions& options);

// Returns 0, or 1 when a reply differs from the model. Throws when the board does not answer or
// the port fails (1, one line naming the port) and host::InputError for bad input (2: file,
// line, column).
int run_stream_command(const StreamOptions& options, std::ostream& out, std::ostream& err);

}  // namespace flange::cli
