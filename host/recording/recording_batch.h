// SPDX-License-Identifier: MIT
// The rows of one block of a recording's lines, read and checked as far as each row alone can be
// checked. That is all of a row's checks but its time order, so any thread can fill a batch; the
// time order waits for the batch reader, which sees the batches in file order.
#pragma once

#include <cstddef>
#include <exception>
#include <string_view>
#include <vector>

#include "line_blocks.h"
#include "recording_columns.h"
#include "recording_row.h"

namespace flange::host {

struct RecordingBatch {
  TextBlock text;  // the lines; the rows' t_texts point into it
  // rows[0, size) are this batch's, in file order; the storage beyond is kept for the next block.
  // A row's problem is what reading its fields found or, for a row that read, its range problem.
  std::vector<RecordingRow> rows;
  // Per row: the text of its t_s field when it read (for the time order's message); empty when
  // reading its fields failed, which leaves the time order unchecked.
  std::vector<std::string_view> t_texts;
  std::size_t size = 0;
  std::size_t last_line = 0;  // the file's line number of the block's last line
  bool end_of_file = false;   // no block was left: the batch has no rows
  std::exception_ptr error;   // what stopped filling the batch, raised when the reader gets to it

  // Reads the rows of `lines` (the whole of text, or its rest after the header) into rows and
  // t_texts; `line` is the line number before the first of them and advances over every line.
  // `fields` is scratch space.
  void read_rows(std::string_view lines, const RecordingColumns& columns, std::size_t& line,
                 std::vector<std::string_view>& fields);
};

}  // namespace flange::host
