// SPDX-License-Identifier: MIT
#include "recording_csv.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>

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

// Refuses a file that is not text: a NUL byte in its first 4 KiB (a spreadsheet's binary format,
// a compressed log, a ROM image).
void refuse_binary(std::ifstream& file, const std::string& path) {
  char block[4096];
  file.read(block, sizeof block);
  const std::string_view head(block, static_cast<std::size_t>(file.gcount()));
  const std::size_t nul = head.find('\0');
  if (nul != std::string_view::npos) {
    throw InputError(fmt::format(
        "{}: not a text file (a zero byte at offset {}); expected a CSV recording with the header "
        "{}",
        path, nul, kExpectedHeader));
  }
  file.clear();
  file.seekg(0);
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
  const char* begin = field.data();
  const char* end = begin + field.size();
  if (begin != end && *begin == '+') ++begin;  // from_chars does not take a leading '+'
  const auto [ptr, ec] = std::from_chars(begin, end, value);
  if (ec != std::errc() || ptr != end || !std::isfinite(value)) return std::nullopt;
  return value;
}

RecordingReader::RecordingReader(const std::string& path, bool lenient)
    : path_(path), lenient_(lenient), file_(path) {
  if (!file_) throw InputError(fmt::format("{}: cannot open the recording", path));
  refuse_binary(file_, path);
  std::string header;
  if (!std::getline(file_, header)) {
    throw InputError(
        fmt::format("{}:1: empty file; expected the header {}", path, kExpectedHeader));
  }
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

std::optional<RecordingRow> RecordingReader::next() {
  while (std::getline(file_, line_buffer_)) {
    ++line_;
    if (line_buffer_.empty() || line_buffer_ == "\r") continue;  // blank lines carry no row
    RecordingRow row;
    row.line = line_;
    split_fields(line_buffer_, fields_);
    std::string problem = check_row(row, fields_);
    ++rows_read_;
    if (!problem.empty()) {
      if (!lenient_) throw InputError(fmt::format("{}:{}: {}", path_, line_, problem));
      row.problem = std::move(problem);
    }
    return row;
  }
  if (rows_read_ == 0) {
    throw InputError(fmt::format("{}:{}: no data rows (the file holds only the header {})", path_,
                                 line_ + 1, kExpectedHeader));
  }
  return std::nullopt;
}

std::string RecordingReader::check_row(RecordingRow& row,
                                       const std::vector<std::string_view>& fields) {
  if (fields.size() != column_count_) {
    return fmt::format("expected {} fields, found {}", column_count_, fields.size());
  }
  auto number = [&](std::size_t column, const char* name, double& out) -> std::string {
    const std::optional<double> value = parse_number(fields[column]);
    if (!value) {
      return fmt::format("column {} ({}): '{}' is not a finite number", column + 1, name,
                         printable_excerpt(fields[column]));
    }
    out = *value;
    return "";
  };
  std::string problem = number(t_column_, "t_s", row.t_s);
  if (problem.empty()) problem = number(temp_column_, "temp_c", row.temp_c);
  if (problem.empty()) problem = number(voltage_column_, "voltage_v", row.voltage_v);
  if (!problem.empty()) return problem;
  if (!fields[clearance_column_].empty()) {
    double clearance = 0.0;
    problem = number(clearance_column_, "clearance_mm", clearance);
    if (!problem.empty()) return problem;
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
    return fmt::format("column {} (voltage_v): {} is outside the sensor's range {} to {} V",
                       voltage_column_ + 1, printable_excerpt(fields[voltage_column_]),
                       kMinVoltageV, kMaxVoltageV);
  }
  if (row.temp_c < kMinTempC || row.temp_c > kMaxTempC) {
    return fmt::format("column {} (temp_c): {} is outside the valid range {} to {} C",
                       temp_column_ + 1, printable_excerpt(fields[temp_column_]), kMinTempC,
                       kMaxTempC);
  }
  return "";
}

}  // namespace flange::host
