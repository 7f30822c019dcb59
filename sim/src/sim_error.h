// SPDX-License-Identifier: MIT
// Errors of the sensor twin and the scenarios, each mapping to a documented exit status.
#pragma once

#include <stdexcept>

namespace flange::sim {

// Exit status of `flange simulate` for input that can never run (README, "Exit status").
inline constexpr int kExitBadArgument = 2;

// An argument, effect parameter or twin-file field is outside its valid range; the message is
// one line naming the argument (or file and field), the value and the range.
class BadArgument : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace flange::sim
