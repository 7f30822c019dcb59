// SPDX-License-Identifier: MIT
// The rows of one block of a recording's lines, read and checked as far as each row alone can be
// checked. That is all of a row's checks but its time order, and a row's line number is counted
// from the block's start, so any thread can fill a batch in any order; the batch reader takes the
// batches in file order, numbers the lines and checks the time order.
#pragma once

#include <cstddef>
#include <cstdint>
#include <exception>
#include <string_view>
#include <vector>

#include "line_blocks.h"
#include "recording_columns.h"
#include "recording_row.h"

namespace flange::host {

struct RecordingBatch {
  std::uint64_t sequence = 0;  // the block's place in the file: 0, 1, 2, ...
  TextBlock text;              // the lines; `lines` and the rows' t_texts point into it
  std::string_view lines;      // the lines to read: all of text, or its rest after the header
  // rows[0, size) are this batch's, in file order, row.line counted from 1 at the block's first
  // line; the storage beyond is kept for the next block. A row's problem is what reading its
  // fields found or, for a row that read, its range problem.
  std::vector<RecordingRow> rows;
  // Per row: the text of its t_s field when it read (for the time order's message); empty when
  // reading its fields failed, which leaves the time order unchecked.
  std::vector<std::string_view> t_texts;
  std::size_t size = 0;
  std::size_t line_count = 0;  // lines in the block, blank ones included
  bool end_of_file = false;    // no block was left: the batch has no rows
  std::exception_ptr error;    // what stopped reading the block, raised when the reader gets to it
  std::vector<std::string_view> fields;  // scratch space of the thread reading the rows

  // Reads the rows of `lines` into rows and t_texts (or the error into `error`).
  void read_rows(const RecordingColumns& columns);
};

}  // namespace flange::host
