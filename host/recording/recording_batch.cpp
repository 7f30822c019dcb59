// SPDX-License-Identifier: MIT
#include "recording_batch.h"

namespace flange::host {

void RecordingBatch::read_rows(std::string_view lines, const RecordingColumns& columns,
                               std::size_t& line, std::vector<std::string_view>& fields) {
  size = 0;
  LineCursor cursor(lines);
  std::string_view line_text;
  while (cursor.next(line_text)) {
    ++line;
    if (is_blank_line(line_text)) continue;
    if (size == rows.size()) {
      rows.emplace_back();
      t_texts.emplace_back();
    }
    RecordingRow& row = rows[size];
    clear_row(row, line);
    split_fields(line_text, fields);
    row.problem = columns.read_fields(row, fields);
    t_texts[size] = {};
    if (row.problem.empty()) {
      t_texts[size] = fields[columns.t_column()];
      row.problem = columns.range_problem(row, fields);
    }
    ++size;
  }
  last_line = line;
}

}  // namespace flange::host
