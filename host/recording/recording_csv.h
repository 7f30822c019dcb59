// SPDX-License-Identifier: MIT
// The recording format every command reads: CSV with header t_s,clearance_mm,temp_c,voltage_v
// (any column order) and an optional run column. Rows are read one at a time from a fixed block
// of the file, so memory stays flat however long the recording is. (recording_batch_reader.h reads
// the same rows in batches, checked on a second thread.)
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "line_blocks.h"
#include "recording_columns.h"
#include "recording_row.h"
#include "time_order.h"

namespace flange::host {

class RecordingReader {
 public:
  // Opens `path` and checks its header; throws InputError naming the file and the column.
  // lenient = false: a bad row throws InputError (file:line: column: value and valid range).
  // lenient = true: a bad row comes back with `problem` set, and reading goes on.
  explicit RecordingReader(const std::string& path, bool lenient = false);

  // Next row, or nullopt at the end of the file.
  std::optional<RecordingRow> next();
  // The same into `row`, reusing its strings (no allocation per row); false at the end of the file.
  bool next(RecordingRow& row);

  bool has_run_column() const { return columns_.has_run_column(); }
  const std::string& path() const { return path_; }
  std::size_t rows_read() const { return rows_read_; }

 private:
  // The next line without its '\n', a view valid until the next call; false at the end of the file.
  bool next_line(std::string_view& line);
  // "" for a good row, else what is wrong with it (file and line are added by the caller).
  std::string check_row(RecordingRow& row, const std::vector<std::string_view>& fields);

  std::string path_;
  bool lenient_;
  FileLineBlocks blocks_;
  TextBlock block_;              // the lines being read
  LineCursor unread_{{}};        // the lines of block_ not yet read
  RecordingColumns columns_;
  TimeOrder time_order_;
  std::size_t line_ = 1;
  std::size_t rows_read_ = 0;
  std::vector<std::string_view> fields_;  // views into block_, reused: no allocation per row
};

}  // namespace flange::host
