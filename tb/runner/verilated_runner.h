// SPDX-License-Identifier: MIT
// The Verilated core is built per coefficient set (its package differs), so `flange cosim` and
// `flange run --engine rtl` build a runner (tb/cosim_main.cpp) the first time they meet a set
// and keep it in a cache folder keyed by the content of the RTL, the set's package and ROM image
// and the runner's sources: $FLANGE_COSIM_CACHE, or <build>/cosim_cache from a build folder, or
// ~/.cache/flange/cosim for an installed flange. The RTL, the runner's sources and the archives
// it links come from the data folder (runtime/data_dir.h).
#pragma once

#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

namespace flange::tb {
namespace fs = std::filesystem;

// The runner for the set of `filter_json`, built first if needed (about 15 s; progress on
// `log`). Throws std::invalid_argument when the package or ROM image is missing beside
// filter.json, std::runtime_error when the build fails or the data folder is not found.
fs::path ensure_verilated_runner(const fs::path& filter_json, std::ostream& log);

// The Verilator the runner is built with: the one found at build time while it exists, otherwise
// `verilator` from PATH.
std::string verilator_program();

// Runs argv[0] with stdout and stderr sent to files; returns the exit status (127 when it could
// not be started).
int spawn_with_files(const std::vector<std::string>& argv, const fs::path& out_file,
                     const fs::path& err_file);
std::string read_whole_file(const fs::path& path);

}  // namespace flange::tb
