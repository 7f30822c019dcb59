// SPDX-License-Identifier: MIT
#include "version_command.h"

#include <sstream>

#include "data_dir.h"
#include "verilated_runner.h"
#include "version.h"

namespace flange::cli {

std::string version_text(std::string_view commit) {
  std::ostringstream text;
  text << "flange " << runtime::version() << "\n"
       << "commit: " << commit << "\n";
  try {
    const runtime::DataDir data = runtime::data_dir();
    text << "data: " << data.root.string() << " (" << runtime::origin_name(data.origin) << ")\n";
  } catch (const runtime::DataDirNotFound& missing) {
    // Recovers: --version reports what it finds, and a missing data folder is one of its answers.
    text << "data: not found (" << missing.what() << ")\n";
  }
  text << "verilator: " << runtime::tool_version({tb::verilator_program(), "--version"}) << "\n"
       << "yosys: " << runtime::tool_version({"yosys", "-V"});
  return text.str();
}

}  // namespace flange::cli
