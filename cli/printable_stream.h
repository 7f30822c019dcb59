// SPDX-License-Identifier: MIT
// The error stream every subcommand writes to, made safe to show: a message that echoes a binary
// file's bytes gets them as \xNN, and a line longer than a screenful is cut. The command line's
// own messages are plain ASCII and pass through unchanged.
#pragma once

#include <cstddef>
#include <ostream>
#include <streambuf>

namespace flange::cli {

class PrintableStreambuf : public std::streambuf {
 public:
  // Lines longer than max_line_chars (after escaping) end in " ... (cut)".
  explicit PrintableStreambuf(std::ostream& target, std::size_t max_line_chars = 1000);

 protected:
  int_type overflow(int_type c) override;
  int sync() override;

 private:
  void put_visible(const char* text, std::size_t size);

  std::ostream& target_;
  std::size_t max_line_chars_;
  std::size_t line_chars_ = 0;
  bool cut_ = false;
};

// An ostream over a PrintableStreambuf.
class PrintableStream : public std::ostream {
 public:
  explicit PrintableStream(std::ostream& target) : std::ostream(&buffer_), buffer_(target) {}

 private:
  PrintableStreambuf buffer_;
};

}  // namespace flange::cli
