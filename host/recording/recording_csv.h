// SPDX-License-Identifier: MIT
// The recording format every command reads: CSV with header t_s,clearance_mm,temp_c,voltage_v
// (any column order) and an optional run column. Rows are read one at a time from a fixed block
// of the file, so memory stays flat however long the recording is.
#pragma once

#include <cstddef>
#include <fstream>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace flange::host {

// Valid ranges of the recorded quantities.
// The sensor's output is 0 to 10 V; a recording may hold up to 1 V beyond either end, where the
// wiring's noise and the converter's offset carry a sample near the rails (a 0.15 V noise reaches
// 0.7 V in a long session). Further out it is not this sensor's signal.
inline constexpr double kSensorMinVoltageV = 0.0, kSensorMaxVoltageV = 10.0;
inline constexpr double kMinVoltageV = kSensorMinVoltageV - 1.0;
inline constexpr double kMaxVoltageV = kSensorMaxVoltageV + 1.0;
inline constexpr double kMinTempC = -40.0, kMaxTempC = 200.0;     // type-K range in use

struct RecordingRow {
  std::size_t line = 0;                // 1-based line in the file
  double t_s = 0.0;                    // time, increasing within a run
  std::optional<double> clearance_mm;  // the reference (micrometer or truth); empty when unknown
  double temp_c = 0.0;                 // thermocouple
  double voltage_v = 0.0;              // sensor output
  std::string run;                     // session label ("" without a run column)
  // Lenient mode only: why the row is bad ("" for a good row). A bad row's numbers are
  // whatever could be parsed; callers must not use them.
  std::string problem;
};

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

  bool has_run_column() const { return run_column_.has_value(); }
  const std::string& path() const { return path_; }
  std::size_t rows_read() const { return rows_read_; }

 private:
  // The next line without its '\n' (as std::getline splits), a view into block_ valid until the
  // next call; false at the end of the file.
  bool next_line(std::string_view& line);
  // Moves the unread rest of block_ to its front and reads more of the file behind it.
  void refill();
  // "" for a good row, else what is wrong with it (file and line are added by the caller).
  std::string check_row(RecordingRow& row, const std::vector<std::string_view>& fields);

  std::string path_;
  bool lenient_;
  std::ifstream file_;
  std::vector<char> block_;  // file bytes [block_begin_, block_end_) not yet split into lines
  std::size_t block_begin_ = 0, block_end_ = 0;
  bool file_done_ = false;
  std::size_t line_ = 1;
  std::size_t rows_read_ = 0;
  std::size_t column_count_ = 0;
  std::size_t t_column_ = 0, clearance_column_ = 0, temp_column_ = 0, voltage_column_ = 0;
  std::optional<std::size_t> run_column_;
  std::optional<double> last_time_;
  std::string last_run_;
  std::vector<std::string_view> fields_;  // views into block_, reused: no allocation per row
};

// Parses a whole field as a finite double; nullopt otherwise.
std::optional<double> parse_number(std::string_view field);

}  // namespace flange::host
