// SPDX-License-Identifier: MIT
#include "input_notes.h"

#include <mutex>
#include <ostream>

namespace flange::host {
namespace {

std::mutex sink_mutex;
std::ostream* sink = nullptr;

}  // namespace

void note_input(const std::string& line) {
  const std::lock_guard<std::mutex> lock(sink_mutex);
  if (sink != nullptr) *sink << "note: " << line << "\n";
}

ScopedInputNotes::ScopedInputNotes(std::ostream& new_sink) {
  const std::lock_guard<std::mutex> lock(sink_mutex);
  previous_ = sink;
  sink = &new_sink;
}

ScopedInputNotes::~ScopedInputNotes() {
  const std::lock_guard<std::mutex> lock(sink_mutex);
  sink = previous_;
}

}  // namespace flange::host
