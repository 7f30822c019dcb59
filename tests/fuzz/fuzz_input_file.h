// SPDX-License-Identifier: MIT
// The loaders under fuzzing read files by path: each input goes to a file of this process's own.
#pragma once

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

namespace flange::fuzz {

inline std::filesystem::path write_fuzz_input(const std::uint8_t* data, std::size_t size,
                                              const char* extension) {
  const std::filesystem::path path = std::filesystem::temp_directory_path() /
                                     ("flange_fuzz_" + std::to_string(::getpid()) + extension);
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(data),
                                              static_cast<std::streamsize>(size));
  return path;
}

}  // namespace flange::fuzz
