// SPDX-License-Identifier: MIT
#include "data_dir.h"

#include <cstdlib>
#include <system_error>

namespace flange::runtime {

namespace {

// The archives of the build folder (CMake's paths of flange_tb and flange_model).
const fs::path kBuildTreeArchives[] = {FLANGE_TB_ARCHIVE, FLANGE_MODEL_ARCHIVE};

// A data folder holds the RTL; the core's top file stands for the rest.
bool holds_data(const fs::path& root) {
  std::error_code ignored;
  return fs::is_regular_file(root / "rtl" / "iir_core.sv", ignored);
}

DataDir data_folder(DataOrigin origin, const fs::path& root, const DataDirSearch& search) {
  DataDir dir;
  dir.origin = origin;
  dir.root = root;
  for (const fs::path& archive : kBuildTreeArchives) {
    dir.runner_archives.push_back(root / "lib" / archive.filename());
  }
  dir.runner_cache = search.user_cache.empty() ? fs::temp_directory_path() / "flange-cosim-cache"
                                               : search.user_cache / "flange" / "cosim";
  return dir;
}

std::optional<fs::path> variable(const char* name) {
  const char* value = std::getenv(name);
  if (value == nullptr || *value == '\0') return std::nullopt;
  return fs::path(value);
}

}  // namespace

DataDir find_data_dir(const DataDirSearch& search) {
  if (search.data_dir_variable) {
    const fs::path root = fs::absolute(*search.data_dir_variable);
    if (!holds_data(root)) {
      throw DataDirNotFound("FLANGE_DATA_DIR=" + root.string() +
                            " holds no rtl/iir_core.sv: point it at an installed share/flange");
    }
    return data_folder(DataOrigin::kEnvironment, root, search);
  }
  const fs::path installed =
      search.executable.empty()
          ? fs::path("<prefix>/share/flange")
          : (search.executable.parent_path() / ".." / "share" / "flange").lexically_normal();
  if (!search.executable.empty() && holds_data(installed)) {
    return data_folder(DataOrigin::kInstalled, installed, search);
  }
  const fs::path source_tree = FLANGE_SOURCE_DIR;
  if (!search.no_source_tree && holds_data(source_tree)) {
    DataDir dir;
    dir.origin = DataOrigin::kSourceTree;
    dir.root = source_tree;
    dir.runner_archives.assign(std::begin(kBuildTreeArchives), std::end(kBuildTreeArchives));
    dir.runner_cache = fs::path(FLANGE_BINARY_DIR) / "cosim_cache";
    return dir;
  }
  const std::string elsewhere = search.no_source_tree
                                    ? " (FLANGE_NO_SOURCE_TREE is set)"
                                    : " nor in the source tree " + source_tree.string();
  throw DataDirNotFound("the data files (rtl/, coeffs/, ...) are not in " + installed.string() +
                        elsewhere + "; set FLANGE_DATA_DIR to an installed share/flange");
}

DataDir data_dir() {
  DataDirSearch search;
  search.data_dir_variable = variable("FLANGE_DATA_DIR");
  search.no_source_tree = variable("FLANGE_NO_SOURCE_TREE").has_value();
  std::error_code failed;
  search.executable = fs::read_symlink("/proc/self/exe", failed);
  if (failed) search.executable.clear();
  if (const std::optional<fs::path> xdg = variable("XDG_CACHE_HOME")) {
    search.user_cache = *xdg;
  } else if (const std::optional<fs::path> home = variable("HOME")) {
    search.user_cache = *home / ".cache";
  }
  return find_data_dir(search);
}

std::string origin_name(DataOrigin origin) {
  switch (origin) {
    case DataOrigin::kEnvironment:
      return "FLANGE_DATA_DIR";
    case DataOrigin::kInstalled:
      return "installed";
    case DataOrigin::kSourceTree:
      return "source tree";
  }
  return "source tree";
}

}  // namespace flange::runtime
