// SPDX-License-Identifier: MIT
// Notes about input that was accepted with a change the user should know of (columns ignored,
// a byte-order mark skipped): one line each. The command line installs a sink (its error stream)
// for the length of a command; without one, notes are dropped.
#pragma once

#include <iosfwd>
#include <string>

namespace flange::host {

// Sends one line (no newline) to the installed sink.
void note_input(const std::string& line);

// Installs `sink` for its lifetime (and restores the previous one after).
class ScopedInputNotes {
 public:
  explicit ScopedInputNotes(std::ostream& sink);
  ~ScopedInputNotes();
  ScopedInputNotes(const ScopedInputNotes&) = delete;
  ScopedInputNotes& operator=(const ScopedInputNotes&) = delete;

 private:
  std::ostream* previous_;
};

}  // namespace flange::host
