// SPDX-License-Identifier: MIT
// Where flange finds the files it reads at run time: the RTL and its scripts (rtl/), the checked-in
// coefficient sets (coeffs/), the sources and headers of the Verilated runner (tb/, model/) and
// the archives the runner links. Every caller asks data_dir(); nothing else knows these places.
//
// The data folder holds rtl/, coeffs/, tb/ and model/ laid out as in the repository. It is, in
// this order:
//   1. $FLANGE_DATA_DIR, when set and not empty (an installed <prefix>/share/flange, or a copy);
//   2. <folder of the executable>/../share/flange, when it holds rtl/iir_core.sv (an installed
//      flange: <prefix>/bin/flange beside <prefix>/share/flange);
//   3. the source tree this flange was built from, with the archives in its build folder (a
//      flange run from its build folder), unless $FLANGE_NO_SOURCE_TREE is set and not empty.
#pragma once

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace flange::runtime {
namespace fs = std::filesystem;

// Which of the three places above the data folder is.
enum class DataOrigin { kEnvironment, kInstalled, kSourceTree };

struct DataDir {
  DataOrigin origin = DataOrigin::kSourceTree;
  fs::path root;  // holds rtl/, coeffs/, tb/ and model/
  // The archives the Verilated runner links, in link order (libflange_tb.a, libflange_model.a):
  // root/lib/ for a data folder, the build folder's for the source tree.
  std::vector<fs::path> runner_archives;
  fs::path runner_cache;  // default folder of built runners ($FLANGE_COSIM_CACHE overrides it)
};

// No data folder was found; the message says where flange looked and how to point it elsewhere.
class DataDirNotFound : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// What the search depends on: the process gives them in data_dir(), tests give their own.
struct DataDirSearch {
  std::optional<fs::path> data_dir_variable;  // $FLANGE_DATA_DIR (empty: unset)
  bool no_source_tree = false;                // $FLANGE_NO_SOURCE_TREE set and not empty
  fs::path executable;                        // /proc/self/exe (empty: unknown)
  fs::path user_cache;                        // $XDG_CACHE_HOME, or $HOME/.cache
};

// The data folder for `search`. Throws DataDirNotFound.
DataDir find_data_dir(const DataDirSearch& search);

// The data folder of this process (its environment and /proc/self/exe). Throws DataDirNotFound.
DataDir data_dir();

// "FLANGE_DATA_DIR", "installed" or "source tree", for `flange --version`.
std::string origin_name(DataOrigin origin);

}  // namespace flange::runtime
