// SPDX-License-Identifier: MIT
// Bad input data: one line that names the file, the line, the column and the valid range.
#pragma once

#include <stdexcept>
#include <string>

namespace flange::host {

// Maps to exit status 2 (kExitBadArgument) in every subcommand.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace flange::host
