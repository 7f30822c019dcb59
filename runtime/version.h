// SPDX-License-Identifier: MIT
// Which flange this is: the project version CMake was given, which every generated file's
// `generated_by` names; and the first line of a tool's own version, for `flange --version`. The
// git commit is recorded in the executable alone (cli/main.cpp), so that a commit relinks one
// program, not every test.
#pragma once

#include <string>
#include <vector>

namespace flange::runtime {

// The project version, e.g. "0.1.0".
std::string version();

// `command` and the version that ran it: "flange design --fs 6 ... (flange 0.1.0)". The commit is
// left out so that a checked-in generated file stays reproducible from one commit to the next.
std::string generated_by(const std::string& command);

// The same for `flange <args...>`, the arguments as given.
std::string generated_by(const std::vector<std::string>& args);

// The first line that `argv` (argv[0] searched in PATH) prints on stdout, or "not found" when it
// cannot be started or exits with a non-zero status.
std::string tool_version(const std::vector<std::string>& argv);

}  // namespace flange::runtime
