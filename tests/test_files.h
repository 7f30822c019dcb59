// SPDX-License-Identifier: MIT
// Small helpers for tests that write input files.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>

namespace flange::testing {

// A fresh, empty folder under the build tree for one test.
inline std::filesystem::path fresh_test_dir(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::path(FLANGE_BINARY_DIR) / "test_files" / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline std::filesystem::path write_file(const std::filesystem::path& path,
                                        const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

}  // namespace flange::testing
