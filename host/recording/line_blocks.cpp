// SPDX-License-Identifier: MIT
#include "line_blocks.h"

#include <fmt/format.h>

#include <algorithm>

#include "input_error.h"

namespace flange::host {

FileLineBlocks::FileLineBlocks(const std::string& path, std::size_t block_bytes)
    : file_(path, std::ios::binary), block_bytes_(block_bytes) {
  if (!file_) throw InputError(fmt::format("{}: cannot open the recording", path));
  TextBlock first;
  first.storage.resize(block_bytes_);
  read_into(first);
  carry_.assign(first.storage.begin(),
                first.storage.begin() + static_cast<std::ptrdiff_t>(first.size));
}

std::string_view FileLineBlocks::head(std::size_t max_bytes) const {
  return {carry_.data(), std::min(carry_.size(), max_bytes)};
}

void FileLineBlocks::read_into(TextBlock& block) {
  if (file_done_) return;
  file_.read(block.storage.data() + block.size,
             static_cast<std::streamsize>(block.storage.size() - block.size));
  block.size += static_cast<std::size_t>(file_.gcount());
  if (!file_) file_done_ = true;  // the end of the file (or a read error, which ends it too)
}

bool FileLineBlocks::next(TextBlock& block) {
  if (block.storage.size() < std::max(block_bytes_, carry_.size())) {
    block.storage.resize(std::max(block_bytes_, carry_.size()));
  }
  std::copy(carry_.begin(), carry_.end(), block.storage.begin());
  block.size = carry_.size();
  carry_.clear();
  for (;;) {
    read_into(block);
    const std::string_view text = block.text();
    const std::size_t last_newline = text.rfind('\n');
    if (last_newline != std::string_view::npos) {
      carry_.assign(text.begin() + static_cast<std::ptrdiff_t>(last_newline) + 1, text.end());
      block.size = last_newline + 1;
      return true;
    }
    if (file_done_) return block.size > 0;  // the last line, without a final '\n'
    block.storage.resize(2 * block.storage.size());  // one line fills the block
  }
}

}  // namespace flange::host
