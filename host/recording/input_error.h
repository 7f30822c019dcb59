// SPDX-License-Identifier: MIT
// Bad input data: one line that names the file, the line, the column and the valid range.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>

namespace flange::host {

// Maps to exit status 2 (kExitBadArgument) in every subcommand.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A value from the input as a message may echo it: bytes outside printable ASCII as \xNN, and cut
// to `max_chars` with "..." so that a binary file or a runaway field cannot flood the line.
std::string printable_excerpt(std::string_view text, std::size_t max_chars = 40);

}  // namespace flange::host
