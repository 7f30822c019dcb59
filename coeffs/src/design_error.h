// SPDX-License-Identifier: MIT
// Errors of the coefficient generator, each carrying the process exit status it maps to.
#pragma once

#include <stdexcept>
#include <string>

namespace flange::coeffs {

// Documented exit statuses of `flange design` (README, "Exit status").
inline constexpr int kExitBadArgument = 2;  // an argument is out of its valid range
inline constexpr int kExitRejected = 3;     // the quantised design is unstable or misses the spec

// Thrown for input that can never make a valid design; the message names the argument and
// its valid range in one line.
class BadArgument : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Thrown when a valid request leads to a design that would not work in hardware; the message
// names the cause and the fix in one line.
class DesignRejected : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace flange::coeffs
