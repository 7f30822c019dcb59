// SPDX-License-Identifier: MIT
// `flange stream`: the command line of host/board_link (a recording through the Basys-3 board's
// filter over its serial port, framed, checked and resent on timeout).
#pragma once

#include <CLI/CLI.hpp>
#include <iosfwd>

#include "stream_session.h"

namespace flange::cli {

CLI::App* add_stream_command(CLI::App& app, host::StreamSettings& options);

// Returns 0; 1 when the board does not answer or the port fails (one line naming the port);
// 2 for bad input (file, line, column).
int run_stream_command(const host::StreamSettings& options, std::ostream& out, std::ostream& err);

}  // namespace flange::cli
