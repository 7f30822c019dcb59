// SPDX-License-Identifier: MIT
// The columns of a recording, from its header, and the checks of a row that need no other row:
// the field count, the numbers, the valid ranges. They are const, so several threads may check
// rows with one RecordingColumns. The time order, which needs the row before, is time_order.h.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "input_error.h"
#include "line_blocks.h"
#include "recording_row.h"

namespace flange::host {

inline constexpr const char* kExpectedRecordingHeader = "t_s,clearance_mm,temp_c,voltage_v[,run]";

// Splits `line` at commas into trimmed views (no allocation once `fields` has grown).
void split_fields(std::string_view line, std::vector<std::string_view>& fields);

// Parses a whole field as a finite double; nullopt otherwise.
std::optional<double> parse_number(std::string_view field);

// Checks that the file is text (no zero byte in its first 4 KiB) and returns its first line, the
// header, from `block`, whose other lines `unread` is left at. Throws InputError.
std::string_view read_recording_header(const std::string& path, FileLineBlocks& blocks,
                                       TextBlock& block, LineCursor& unread);
// The error of a file that ends after the header and `last_line` lines (blank ones).
InputError no_data_rows(const std::string& path, std::size_t last_line);

class RecordingColumns {
 public:
  // From the header line of `path`; throws InputError naming the file and the column. Notes the
  // columns it ignores (note_input).
  RecordingColumns(const std::string& path, std::string_view header_line);

  // Fills `row` from its fields: "" when every field reads, else what is wrong (file and line are
  // added by the caller) with the numbers read so far in `row`.
  std::string read_fields(RecordingRow& row, const std::vector<std::string_view>& fields) const;
  // For a row that read: "" when its voltage and temperature are in range, else which is not.
  std::string range_problem(const RecordingRow& row,
                            const std::vector<std::string_view>& fields) const;

  // The usual row at a third of the cost: when the header has exactly the four columns, reads a
  // line whose four fields std::from_chars takes whole (no blanks, no '+', no empty clearance)
  // and whose voltage and temperature are in range, without splitting it. Returns false for any
  // other line (and `row`'s numbers are then undefined): read_fields and range_problem decide it,
  // as they would have anyway. `t_text` gets the t_s field.
  bool read_plain_line(RecordingRow& row, std::string_view line, std::string_view& t_text) const;

  std::size_t t_column() const { return t_; }
  bool has_run_column() const { return run_.has_value(); }

 private:
  std::size_t count_ = 0;
  std::size_t t_ = 0, clearance_ = 0, temp_ = 0, voltage_ = 0;
  std::optional<std::size_t> run_;
  bool plain_ = false;  // the header is the four columns, in any order
};

}  // namespace flange::host
