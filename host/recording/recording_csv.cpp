// SPDX-License-Identifier: MIT
#include "recording_csv.h"

#include <fmt/format.h>

#include "input_error.h"

namespace flange::host {

std::string printable_excerpt(std::string_view text, std::size_t max_chars) {
  std::string out;
  std::size_t shown = 0;
  for (const char c : text) {
    if (shown == max_chars) return out + "...";
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x20 && byte < 0x7f) {
      out += c;
    } else {
      out += fmt::format("\\x{:02X}", byte);
    }
    ++shown;
  }
  return out;
}

RecordingReader::RecordingReader(const std::string& path, bool lenient)
    : path_(path),
      lenient_(lenient),
      blocks_(path),
      columns_(path, read_recording_header(path, blocks_, block_, unread_)) {}

bool RecordingReader::next_line(std::string_view& line) {
  while (!unread_.next(line)) {
    if (!blocks_.next(block_)) return false;
    unread_ = LineCursor(block_.text());
  }
  return true;
}

std::optional<RecordingRow> RecordingReader::next() {
  RecordingRow row;
  if (!next(row)) return std::nullopt;
  return row;
}

bool RecordingReader::next(RecordingRow& row) {
  std::string_view line;
  while (next_line(line)) {
    ++line_;
    if (is_blank_line(line)) continue;  // blank lines carry no row
    clear_row(row, line_);
    split_fields(line, fields_);
    std::string problem = check_row(row, fields_);
    ++rows_read_;
    if (!problem.empty()) {
      if (!lenient_) throw InputError(fmt::format("{}:{}: {}", path_, line_, problem));
      row.problem = std::move(problem);
    }
    return true;
  }
  if (rows_read_ == 0) throw no_data_rows(path_, line_);
  return false;
}

std::string RecordingReader::check_row(RecordingRow& row,
                                       const std::vector<std::string_view>& fields) {
  std::string problem = columns_.read_fields(row, fields);
  if (problem.empty() && !time_order_.passes(row)) {
    problem = time_order_.problem(fields[columns_.t_column()], columns_.t_column());
  }
  if (problem.empty()) problem = columns_.range_problem(row, fields);
  return problem;
}

}  // namespace flange::host
