// SPDX-License-Identifier: MIT
// The one table from an exception to an exit status (cli/README.md, "Exit status"): commands
// only throw, and the dispatch in cli.cpp turns what they throw into the status and one line
// on stderr that starts with the subcommand's name.
#pragma once

#include <exception>
#include <functional>
#include <iosfwd>
#include <stdexcept>
#include <string>
#include <string_view>

namespace flange::cli {

// The statuses, the same for every subcommand.
inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;      // a check failed or a file could not be read/written
inline constexpr int kExitBadArgument = 2;  // an argument or input value is out of its range
inline constexpr int kExitDefect = 3;       // a valid request with a defect a check found

// The status of an exception a command threw: the first row of the table it is an instance of
// (a bad input 2, a design that would not work in hardware 3), 1 for any other.
int exit_status_of(const std::exception& error);

// An exception of a step that one option's value drives, with the option before its message
// ("--store: store mysql://x: ...") and the status of the exception it replaces.
class OptionError : public std::runtime_error {
 public:
  OptionError(std::string_view option, const std::exception& cause);
  int status() const { return status_; }

 private:
  int status_;
};

// Runs `step`; what it throws reaches the table as an OptionError naming `option`.
void naming_option(std::string_view option, const std::function<void()>& step);

// The line and the status for an exception that ended `command` ("flange design"): prints
// "<command>: <message>" on `err` and returns the status.
int report_exit(std::string_view command, const std::exception& error, std::ostream& err);

}  // namespace flange::cli
