// SPDX-License-Identifier: MIT
// The recording reader on any bytes: rows or one InputError, strict and lenient; nothing else may
// escape, and every message is one printable line. The batch reader (with and without its second
// thread) returns the same rows and the same error.
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include "fuzz_input_file.h"
#include "input_error.h"
#include "recording_batch_reader.h"
#include "recording_csv.h"

namespace {

void check_message(const std::string& message) {
  for (const char c : message) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte >= 0x7f) std::abort();  // a raw byte reached the message
  }
}

// A row as text, to compare the readers by; an error is a last "row".
std::string row_text(const flange::host::RecordingRow& row) {
  return std::to_string(row.line) + " " + std::to_string(row.t_s) + " " +
         (row.clearance_mm ? std::to_string(*row.clearance_mm) : "-") + " " +
         std::to_string(row.temp_c) + " " + std::to_string(row.voltage_v) + " " + row.run + " " +
         row.problem;
}

std::vector<std::string> read_all(const std::string& path, bool lenient) {
  std::vector<std::string> rows;
  try {
    flange::host::RecordingReader reader(path, lenient);
    while (const std::optional<flange::host::RecordingRow> row = reader.next()) {
      if (!lenient && !row->problem.empty()) std::abort();
      check_message(row->problem);
      rows.push_back(row_text(*row));
    }
  } catch (const flange::host::InputError& error) {
    // The path is ours and printable; the rest of the message must be too.
    check_message(error.what());
    rows.push_back(error.what());
  }
  return rows;
}

std::vector<std::string> read_in_batches(const std::string& path, bool lenient, bool read_ahead) {
  std::vector<std::string> rows;
  try {
    flange::host::RecordingBatchReader reader(path, lenient, read_ahead);
    for (std::span<const flange::host::RecordingRow> batch;
         !(batch = reader.next_rows()).empty();) {
      for (const flange::host::RecordingRow& row : batch) rows.push_back(row_text(row));
    }
  } catch (const flange::host::InputError& error) {
    rows.push_back(error.what());
  }
  return rows;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = flange::fuzz::write_fuzz_input(data, size, ".csv").string();
  for (const bool lenient : {false, true}) {
    const std::vector<std::string> rows = read_all(path, lenient);
    for (const bool read_ahead : {false, true}) {
      if (read_in_batches(path, lenient, read_ahead) != rows) std::abort();
    }
  }
  return 0;
}
