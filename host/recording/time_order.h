// SPDX-License-Identifier: MIT
// Time restarts with each run of a recording; within one it must increase. The one check of a row
// that needs the row before, so rows pass it one at a time, in file order.
#pragma once

#include <fmt/format.h>

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "input_error.h"
#include "recording_row.h"

namespace flange::host {

class TimeOrder {
 public:
  // Whether `row` (which read well) comes after the last row that passed; if so it becomes the
  // last. Inline and without a string: it runs for every row, on the thread that keeps the order.
  bool passes(const RecordingRow& row) {
    if (last_time_.has_value() && row.run == last_run_ && !(row.t_s > *last_time_)) return false;
    last_time_ = row.t_s;
    if (last_run_ != row.run) last_run_ = row.run;
    return true;
  }
  // Why `row` did not pass, naming the column `t_column` (0-based) and its text `t_text`.
  std::string problem(std::string_view t_text, std::size_t t_column) const {
    return fmt::format("column {} (t_s): {} is not after the previous time {}", t_column + 1,
                       printable_excerpt(t_text), *last_time_);
  }

 private:
  std::optional<double> last_time_;
  std::string last_run_;
};

}  // namespace flange::host
