// SPDX-License-Identifier: MIT
#include "printable_stream.h"

#include <cstdio>

namespace flange::cli {

PrintableStreambuf::PrintableStreambuf(std::ostream& target, std::size_t max_line_chars)
    : target_(target), max_line_chars_(max_line_chars) {}

void PrintableStreambuf::put_visible(const char* text, std::size_t size) {
  if (cut_) return;
  if (line_chars_ + size > max_line_chars_) {
    target_ << " ... (cut)";
    cut_ = true;
    return;
  }
  target_.write(text, static_cast<std::streamsize>(size));
  line_chars_ += size;
}

PrintableStreambuf::int_type PrintableStreambuf::overflow(int_type c) {
  if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
  const auto byte = static_cast<unsigned char>(traits_type::to_char_type(c));
  if (byte == '\n') {
    target_.put('\n');
    line_chars_ = 0;
    cut_ = false;
  } else if ((byte >= 0x20 && byte < 0x7f) || byte == '\t') {
    const char plain = static_cast<char>(byte);
    put_visible(&plain, 1);
  } else {
    char escaped[5];
    std::snprintf(escaped, sizeof escaped, "\\x%02X", byte);
    put_visible(escaped, 4);
  }
  return c;
}

int PrintableStreambuf::sync() {
  target_.flush();
  return 0;
}

}  // namespace flange::cli
