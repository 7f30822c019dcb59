// SPDX-License-Identifier: MIT
// A text file as blocks of whole lines: one read call per block and a fixed block size however
// long the file is (a single longer line grows it). A block can be handed to another thread to
// split and parse while the next one is read.
#pragma once

#include <cstddef>
#include <cstring>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

namespace flange::host {

// Bytes read from the file at a time: few system calls, little memory.
inline constexpr std::size_t kLineBlockBytes = std::size_t{1} << 20;

// Whole lines of a file; the storage is kept from block to block (no allocation per block).
struct TextBlock {
  std::vector<char> storage;
  std::size_t size = 0;  // bytes of lines in storage
  std::string_view text() const { return {storage.data(), size}; }
};

class FileLineBlocks {
 public:
  // Opens `path` and reads its first block; throws InputError when the file cannot be opened.
  explicit FileLineBlocks(const std::string& path, std::size_t block_bytes = kLineBlockBytes);

  // The first bytes of the file (at most `max_bytes` and one block), before any next().
  std::string_view head(std::size_t max_bytes) const;
  // Replaces `block` with the next whole lines of the file, each ending in '\n' but the file's
  // last line, which may lack it; false once the file is done.
  bool next(TextBlock& block);

 private:
  // Appends to `block` from the file up to its storage's size.
  void read_into(TextBlock& block);

  std::ifstream file_;
  std::size_t block_bytes_;
  // Read from the file but not yet in a block: the start of a line that the last read cut.
  std::vector<char> carry_;
  bool file_done_ = false;
};

// The lines of one block in order, without their '\n' (as std::getline splits).
class LineCursor {
 public:
  explicit LineCursor(std::string_view text) : rest_(text) {}
  bool next(std::string_view& line) {
    if (rest_.empty()) return false;
    const void* newline = std::memchr(rest_.data(), '\n', rest_.size());
    const std::size_t length = newline == nullptr
                                   ? rest_.size()  // the file's last line, without a final '\n'
                                   : static_cast<std::size_t>(
                                         static_cast<const char*>(newline) - rest_.data());
    line = rest_.substr(0, length);
    rest_.remove_prefix(newline == nullptr ? length : length + 1);
    return true;
  }
  // What next() has not returned yet.
  std::string_view rest() const { return rest_; }

 private:
  std::string_view rest_;
};

}  // namespace flange::host
