// SPDX-License-Identifier: MIT
// The `flange` command line: one entry point for every subcommand, callable in-process so that
// tests run exactly what users run.
#pragma once

#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

#include "exit_status.h"
#include "version_command.h"

namespace flange::cli {

// Runs `flange <args...>` and returns its exit status. `commit` is the git commit `flange
// --version` names: main.cpp passes the one recorded at build time.
int run_flange(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
               std::string_view commit = kCommitNotRecorded);

}  // namespace flange::cli
