// SPDX-License-Identifier: MIT
#include "recording_csv.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>

#include "input_error.h"
#include "input_notes.h"

namespace flange::host {

namespace {

constexpr const char* kExpectedHeader = "t_s,clearance_mm,temp_c,voltage_v[,run]";

// Splits `line` at commas into trimmed views (no allocation once `fields` has grown).
void split_fields(std::string_view line, std::vector<std::string_view>& fields) {
  fields.clear();
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = line.find(',', start);
    std::string_view field = line.substr(
        start, comma == std::string_view::npos ? std::string_view::npos : comma - start);
    while (!field.empty() && (field.front() == ' ' || field.front() == '\t'))
      field.remove_prefix(1);
    while (!field.empty() && (field.back() == ' ' || field.back() == '\t')) field.remove_suffix(1);
    fields.push_back(field);
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
}

// Bytes read from the file at a time: few system calls, and a fixed block of memory however long
// the recording is (a single longer line grows it).
constexpr std::size_t kBlockBytes = std::size_t{1} << 20;
// A file with a NUL byte in its first 4 KiB is not text (a spreadsheet's binary format, a
// compressed log, a ROM image).
constexpr std::size_t kBinaryProbeBytes = 4096;

// parse_number into `out`; false (and `out` untouched) when the field is not a finite number.
bool parse_into(std::string_view field, double& out) {
  double value = 0.0;
  const char* begin = field.data();
  const char* end = begin + field.size();
  if (begin != end && *begin == '+') ++begin;  // from_chars does not take a leading '+'
  const auto [ptr, ec] = std::from_chars(begin, end, value);
  if (ec != std::errc() || ptr != end || !std::isfinite(value)) return false;
  out = value;
  return true;
}

std::string not_a_number(std::size_t column, const char* name, std::string_view field) {
  return fmt::format("column {} ({}): '{}' is not a finite number", column + 1, name,
                     printable_excerpt(field));
}

}  // namespace

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

std::optional<double> parse_number(std::string_view field) {
  double value = 0.0;
  if (!parse_into(field, value)) return std::nullopt;
  return value;
}

RecordingReader::RecordingReader(const std::string& path, bool lenient)
    : path_(path), lenient_(lenient), file_(path, std::ios::binary), block_(kBlockBytes) {
  if (!file_) throw InputError(fmt::format("{}: cannot open the recording", path));
  refill();
  const std::string_view head(block_.data(), std::min(block_end_, kBinaryProbeBytes));
  const std::size_t nul = head.find('\0');
  if (nul != std::string_view::npos) {
    throw InputError(fmt::format(
        "{}: not a text file (a zero byte at offset {}); expected a CSV recording with the header "
        "{}",
        path, nul, kExpectedHeader));
  }
  std::string_view header_line;
  if (!next_line(header_line)) {
    throw InputError(
        fmt::format("{}:1: empty file; expected the header {}", path, kExpectedHeader));
  }
  std::string header(header_line);
  // A spreadsheet saving "CSV UTF-8" puts a byte-order mark before the first column name.
  if (header.rfind("\xEF\xBB\xBF", 0) == 0) header.erase(0, 3);
  std::vector<std::string_view> name_views;
  split_fields(header, name_views);
  const std::vector<std::string> names(name_views.begin(), name_views.end());
  column_count_ = names.size();
  std::optional<std::size_t> t, clearance, temp, voltage;
  std::string ignored;
  for (std::size_t i = 0; i < names.size(); ++i) {
    std::optional<std::size_t>* slot = nullptr;
    if (names[i] == "t_s") slot = &t;
    if (names[i] == "clearance_mm") slot = &clearance;
    if (names[i] == "temp_c") slot = &temp;
    if (names[i] == "voltage_v") slot = &voltage;
    if (names[i] == "run") slot = &run_column_;
    if (slot == nullptr) {
      // A logger's extra columns (humidity, speed, ...) are not part of the format: skipped.
      ignored += fmt::format("{}'{}'", ignored.empty() ? "" : ", ", printable_excerpt(names[i]));
      continue;
    }
    if (slot->has_value()) {
      throw InputError(fmt::format("{}:1: column {}: '{}' appears twice", path, i + 1,
                                   printable_excerpt(names[i])));
    }
    *slot = i;
  }
  const std::pair<const char*, std::optional<std::size_t>*> required[] = {
      {"t_s", &t}, {"clearance_mm", &clearance}, {"temp_c", &temp}, {"voltage_v", &voltage}};
  for (const auto& [name, slot] : required) {
    if (!slot->has_value()) {
      throw InputError(
          fmt::format("{}:1: missing column '{}' (expected {})", path, name, kExpectedHeader));
    }
  }
  if (!ignored.empty()) {
    note_input(fmt::format("{}:1: ignoring column(s) {}: not part of the recording format {}", path,
                           ignored, kExpectedHeader));
  }
  t_column_ = *t;
  clearance_column_ = *clearance;
  temp_column_ = *temp;
  voltage_column_ = *voltage;
}

void RecordingReader::refill() {
  const std::size_t unread = block_end_ - block_begin_;
  if (block_begin_ > 0) {
    std::copy(block_.begin() + static_cast<std::ptrdiff_t>(block_begin_),
              block_.begin() + static_cast<std::ptrdiff_t>(block_end_), block_.begin());
    block_begin_ = 0;
  }
  block_end_ = unread;
  if (block_end_ == block_.size()) block_.resize(2 * block_.size());  // one line fills the block
  file_.read(block_.data() + block_end_, static_cast<std::streamsize>(block_.size() - block_end_));
  block_end_ += static_cast<std::size_t>(file_.gcount());
  if (!file_) file_done_ = true;  // the end of the file (or a read error, which ends it too)
}

bool RecordingReader::next_line(std::string_view& line) {
  for (;;) {
    const char* begin = block_.data() + block_begin_;
    const std::size_t available = block_end_ - block_begin_;
    if (const void* newline = std::memchr(begin, '\n', available)) {
      const auto length = static_cast<std::size_t>(static_cast<const char*>(newline) - begin);
      line = std::string_view(begin, length);
      block_begin_ += length + 1;
      return true;
    }
    if (file_done_) {
      if (available == 0) return false;
      line = std::string_view(begin, available);  // the last line, without a final '\n'
      block_begin_ = block_end_;
      return true;
    }
    refill();
  }
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
    if (line.empty() || line == "\r") continue;  // blank lines carry no row
    // A fresh row, but with the strings' storage kept.
    row.line = line_;
    row.t_s = row.temp_c = row.voltage_v = 0.0;
    row.clearance_mm.reset();
    row.run.clear();
    row.problem.clear();
    split_fields(line, fields_);
    std::string problem = check_row(row, fields_);
    ++rows_read_;
    if (!problem.empty()) {
      if (!lenient_) throw InputError(fmt::format("{}:{}: {}", path_, line_, problem));
      row.problem = std::move(problem);
    }
    return true;
  }
  if (rows_read_ == 0) {
    throw InputError(fmt::format("{}:{}: no data rows (the file holds only the header {})", path_,
                                 line_ + 1, kExpectedHeader));
  }
  return false;
}

std::string RecordingReader::check_row(RecordingRow& row,
                                       const std::vector<std::string_view>& fields) {
  if (fields.size() != column_count_) {
    return fmt::format("expected {} fields, found {}", column_count_, fields.size());
  }
  if (!parse_into(fields[t_column_], row.t_s)) {
    return not_a_number(t_column_, "t_s", fields[t_column_]);
  }
  if (!parse_into(fields[temp_column_], row.temp_c)) {
    return not_a_number(temp_column_, "temp_c", fields[temp_column_]);
  }
  if (!parse_into(fields[voltage_column_], row.voltage_v)) {
    return not_a_number(voltage_column_, "voltage_v", fields[voltage_column_]);
  }
  if (!fields[clearance_column_].empty()) {
    double clearance = 0.0;
    if (!parse_into(fields[clearance_column_], clearance)) {
      return not_a_number(clearance_column_, "clearance_mm", fields[clearance_column_]);
    }
    row.clearance_mm = clearance;
  }
  if (run_column_) row.run = fields[*run_column_];
  // Time restarts with each run; within one it must increase.
  const bool same_run = last_time_.has_value() && row.run == last_run_;
  if (same_run && !(row.t_s > *last_time_)) {
    return fmt::format("column {} (t_s): {} is not after the previous time {}", t_column_ + 1,
                       printable_excerpt(fields[t_column_]), *last_time_);
  }
  last_time_ = row.t_s;
  last_run_ = row.run;
  if (row.voltage_v < kMinVoltageV || row.voltage_v > kMaxVoltageV) {
    return fmt::format(
        "column {} (voltage_v): {} is outside the valid range {} to {} V (the sensor's {} to {} V "
        "and 1 V either side for noise)",
        voltage_column_ + 1, printable_excerpt(fields[voltage_column_]), kMinVoltageV,
        kMaxVoltageV, kSensorMinVoltageV, kSensorMaxVoltageV);
  }
  if (row.temp_c < kMinTempC || row.temp_c > kMaxTempC) {
    return fmt::format("column {} (temp_c): {} is outside the valid range {} to {} C",
                       temp_column_ + 1, printable_excerpt(fields[temp_column_]), kMinTempC,
                       kMaxTempC);
  }
  return "";
}

}  // namespace flange::host
