// SPDX-License-Identifier: MIT
#include "recording_columns.h"

#include <fast_float/fast_float.h>
#include <fmt/format.h>

#include <cmath>
#include <utility>

#include "input_error.h"
#include "input_notes.h"

namespace flange::host {

namespace {

// A file with a NUL byte in its first 4 KiB is not text (a spreadsheet's binary format, a
// compressed log, a ROM image).
constexpr std::size_t kBinaryProbeBytes = 4096;

std::string not_a_number(std::size_t column, const char* name, std::string_view field) {
  return fmt::format("column {} ({}): '{}' is not a finite number", column + 1, name,
                     printable_excerpt(field));
}

// parse_number into `out`; false (and `out` untouched) when the field is not a finite number.
bool parse_into(std::string_view field, double& out) {
  double value = 0.0;
  const char* begin = field.data();
  const char* end = begin + field.size();
  if (begin != end && *begin == '+') ++begin;  // from_chars does not take a leading '+'
  const auto [ptr, ec] = fast_float::from_chars(begin, end, value);
  if (ec != std::errc() || ptr != end || !std::isfinite(value)) return false;
  out = value;
  return true;
}

}  // namespace

std::optional<double> parse_number(std::string_view field) {
  double value = 0.0;
  if (!parse_into(field, value)) return std::nullopt;
  return value;
}

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

std::string_view read_recording_header(const std::string& path, FileLineBlocks& blocks,
                                       TextBlock& block, LineCursor& unread) {
  const std::string_view head = blocks.head(kBinaryProbeBytes);
  const std::size_t nul = head.find('\0');
  if (nul != std::string_view::npos) {
    throw InputError(fmt::format(
        "{}: not a text file (a zero byte at offset {}); expected a CSV recording with the header "
        "{}",
        path, nul, kExpectedRecordingHeader));
  }
  std::string_view header;
  if (blocks.next(block)) unread = LineCursor(block.text());
  if (!unread.next(header)) {
    throw InputError(
        fmt::format("{}:1: empty file; expected the header {}", path, kExpectedRecordingHeader));
  }
  return header;
}

InputError no_data_rows(const std::string& path, std::size_t last_line) {
  return InputError(fmt::format("{}:{}: no data rows (the file holds only the header {})", path,
                                last_line + 1, kExpectedRecordingHeader));
}

RecordingColumns::RecordingColumns(const std::string& path, std::string_view header_line) {
  std::string header(header_line);
  // A spreadsheet saving "CSV UTF-8" puts a byte-order mark before the first column name.
  if (header.rfind("\xEF\xBB\xBF", 0) == 0) header.erase(0, 3);
  std::vector<std::string_view> name_views;
  split_fields(header, name_views);
  const std::vector<std::string> names(name_views.begin(), name_views.end());
  count_ = names.size();
  std::optional<std::size_t> t, clearance, temp, voltage;
  std::string ignored;
  for (std::size_t i = 0; i < names.size(); ++i) {
    std::optional<std::size_t>* slot = nullptr;
    if (names[i] == "t_s") slot = &t;
    if (names[i] == "clearance_mm") slot = &clearance;
    if (names[i] == "temp_c") slot = &temp;
    if (names[i] == "voltage_v") slot = &voltage;
    if (names[i] == "run") slot = &run_;
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
      throw InputError(fmt::format("{}:1: missing column '{}' (expected {})", path, name,
                                   kExpectedRecordingHeader));
    }
  }
  if (!ignored.empty()) {
    note_input(fmt::format("{}:1: ignoring column(s) {}: not part of the recording format {}", path,
                           ignored, kExpectedRecordingHeader));
  }
  t_ = *t;
  clearance_ = *clearance;
  temp_ = *temp;
  voltage_ = *voltage;
  plain_ = count_ == 4 && !run_;
}

bool RecordingColumns::read_plain_line(RecordingRow& row, std::string_view line,
                                       std::string_view& t_text) const {
  if (!plain_) return false;
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  const char* at = line.data();
  const char* const end = at + line.size();
  double values[4];
  const char* starts[4];
  for (int i = 0; i < 4; ++i) {
    // from_chars neither skips blanks nor takes '+': such a field stops it at once. A field it
    // takes up to the comma (or the line's end) is what split_fields and parse_number would read.
    starts[i] = at;
    const auto [ptr, ec] = fast_float::from_chars(at, end, values[i]);
    if (ec != std::errc() || ptr == at || !std::isfinite(values[i])) return false;
    if (i < 3) {
      if (ptr == end || *ptr != ',') return false;
      at = ptr + 1;
    } else if (ptr != end) {
      return false;
    }
  }
  row.t_s = values[t_];
  row.clearance_mm = values[clearance_];
  row.temp_c = values[temp_];
  row.voltage_v = values[voltage_];
  if (row.voltage_v < kMinVoltageV || row.voltage_v > kMaxVoltageV || row.temp_c < kMinTempC ||
      row.temp_c > kMaxTempC) {
    return false;
  }
  t_text = std::string_view(
      starts[t_], static_cast<std::size_t>((t_ < 3 ? starts[t_ + 1] - 1 : end) - starts[t_]));
  return true;
}

std::string RecordingColumns::read_fields(RecordingRow& row,
                                          const std::vector<std::string_view>& fields) const {
  if (fields.size() != count_) {
    return fmt::format("expected {} fields, found {}", count_, fields.size());
  }
  if (!parse_into(fields[t_], row.t_s)) return not_a_number(t_, "t_s", fields[t_]);
  if (!parse_into(fields[temp_], row.temp_c)) return not_a_number(temp_, "temp_c", fields[temp_]);
  if (!parse_into(fields[voltage_], row.voltage_v)) {
    return not_a_number(voltage_, "voltage_v", fields[voltage_]);
  }
  if (!fields[clearance_].empty()) {
    double clearance = 0.0;
    if (!parse_into(fields[clearance_], clearance)) {
      return not_a_number(clearance_, "clearance_mm", fields[clearance_]);
    }
    row.clearance_mm = clearance;
  }
  if (run_) row.run = fields[*run_];
  return "";
}

std::string RecordingColumns::range_problem(const RecordingRow& row,
                                            const std::vector<std::string_view>& fields) const {
  if (row.voltage_v < kMinVoltageV || row.voltage_v > kMaxVoltageV) {
    return fmt::format(
        "column {} (voltage_v): {} is outside the valid range {} to {} V (the sensor's {} to {} V "
        "and 1 V either side for noise)",
        voltage_ + 1, printable_excerpt(fields[voltage_]), kMinVoltageV, kMaxVoltageV,
        kSensorMinVoltageV, kSensorMaxVoltageV);
  }
  if (row.temp_c < kMinTempC || row.temp_c > kMaxTempC) {
    return fmt::format("column {} (temp_c): {} is outside the valid range {} to {} C", temp_ + 1,
                       printable_excerpt(fields[temp_]), kMinTempC, kMaxTempC);
  }
  return "";
}

}  // namespace flange::host
