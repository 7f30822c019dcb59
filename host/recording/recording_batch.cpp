// SPDX-License-Identifier: MIT
#include "recording_batch.h"

namespace flange::host {

void RecordingBatch::read_rows(const RecordingColumns& columns) {
  size = 0;
  line_count = 0;
  try {
    LineCursor cursor(lines);
    std::string_view line_text;
    while (cursor.next(line_text)) {
      ++line_count;
      if (is_blank_line(line_text)) continue;
      if (size == rows.size()) {
        rows.emplace_back();
        t_texts.emplace_back();
      }
      RecordingRow& row = rows[size];
      clear_row(row, line_count);
      if (columns.read_plain_line(row, line_text, t_texts[size])) {
        ++size;
        continue;
      }
      clear_row(row, line_count);  // the general reading below decides the line
      split_fields(line_text, fields);
      row.problem = columns.read_fields(row, fields);
      t_texts[size] = {};
      if (row.problem.empty()) {
        t_texts[size] = fields[columns.t_column()];
        row.problem = columns.range_problem(row, fields);
      }
      ++size;
    }
  } catch (...) {
    error = std::current_exception();  // bad_alloc on a huge line: raised in file order
  }
}

}  // namespace flange::host
