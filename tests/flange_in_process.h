// SPDX-License-Identifier: MIT
// `flange <args...>` run in-process, exactly as users run it, with what it printed: the helper
// every command-line test uses.
#pragma once

#include <sstream>
#include <string>
#include <vector>

#include "cli.h"

namespace flange::testing {

struct FlangeOutcome {
  int status = 0;
  std::string out, err;
};

// The command line as a user would type it, for failure messages.
inline std::string command_text(const std::vector<std::string>& args) {
  std::string text = "flange";
  for (const std::string& arg : args) text += " " + arg;
  return text;
}

inline FlangeOutcome run_flange_captured(const std::vector<std::string>& args) {
  std::ostringstream out, err;
  const int status = cli::run_flange(args, out, err);
  return {status, out.str(), err.str()};
}

}  // namespace flange::testing
