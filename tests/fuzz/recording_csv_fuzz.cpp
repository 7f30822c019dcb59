// SPDX-License-Identifier: MIT
// The recording reader on any bytes: rows or one InputError, strict and lenient; nothing else may
// escape, and every message is one printable line.
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <string>

#include "fuzz_input_file.h"
#include "input_error.h"
#include "recording_csv.h"

namespace {

void check_message(const std::string& message) {
  for (const char c : message) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte >= 0x7f) std::abort();  // a raw byte reached the message
  }
}

void read_all(const std::string& path, bool lenient) {
  try {
    flange::host::RecordingReader reader(path, lenient);
    while (const std::optional<flange::host::RecordingRow> row = reader.next()) {
      if (!lenient && !row->problem.empty()) std::abort();
      check_message(row->problem);
    }
  } catch (const flange::host::InputError& error) {
    // The path is ours and printable; the rest of the message must be too.
    check_message(error.what());
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = flange::fuzz::write_fuzz_input(data, size, ".csv").string();
  read_all(path, false);
  read_all(path, true);
  return 0;
}
