// SPDX-License-Identifier: MIT
// `flange --version`: the version, the git commit the executable was built from, the data folder
// it reads (runtime/data_dir.h) and the Verilator and Yosys it finds, for bug reports.
#pragma once

#include <string>
#include <string_view>

namespace flange::cli {

// What the version text says of a commit nobody recorded (in-process callers such as the tests;
// the executable passes the commit CMake recorded, "unknown" outside a git checkout).
inline constexpr std::string_view kCommitNotRecorded = "not recorded (not the flange executable)";

// Lines "flange <version>", "commit: ...", "data: <folder> (<origin>)", "verilator: ...",
// "yosys: ..."; a tool that cannot be run is "not found".
std::string version_text(std::string_view commit);

}  // namespace flange::cli
