// SPDX-License-Identifier: MIT
#include "recording_csv.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>

#include "input_error.h"

namespace flange::host {

namespace {

constexpr const char* kExpectedHeader = "t_s,clearance_mm,temp_c,voltage_v[,run]";

std::vector<std::string> split_fields(const std::string& line) {
  std::vector<std::string> fields;
  std::string field;
  for (char c : line) {
    if (c == ',') {
      fields.push_back(field);
      field.clear();
    } else if (c != '\r') {
      field.push_back(c);
    }
  }
  fields.push_back(field);
  for (std::string& f : fields) {
    const auto first = f.find_first_not_of(" \t");
    const auto last = f.find_last_not_of(" \t");
    f = first == std::string::npos ? "" : f.substr(first, last - first + 1);
  }
  return fields;
}

}  // namespace

std::optional<double> parse_number(const std::string& field) {
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
  std::string header;
  if (!std::getline(file_, header)) {
    throw InputError(
        fmt::format("{}:1: empty file; expected the header {}", path, kExpectedHeader));
  }
  const std::vector<std::string> names = split_fields(header);
  column_count_ = names.size();
  std::optional<std::size_t> t, clearance, temp, voltage;
  for (std::size_t i = 0; i < names.size(); ++i) {
    std::optional<std::size_t>* slot = nullptr;
    if (names[i] == "t_s") slot = &t;
    if (names[i] == "clearance_mm") slot = &clearance;
    if (names[i] == "temp_c") slot = &temp;
    if (names[i] == "voltage_v") slot = &voltage;
    if (names[i] == "run") slot = &run_column_;
    if (slot == nullptr) {
      throw InputError(fmt::format("{}:1: column {}: unknown column '{}' (expected {})", path,
                                   i + 1, names[i], kExpectedHeader));
    }
    if (slot->has_value()) {
      throw InputError(fmt::format("{}:1: column {}: '{}' appears twice", path, i + 1, names[i]));
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
  t_column_ = *t;
  clearance_column_ = *clearance;
  temp_column_ = *temp;
  voltage_column_ = *voltage;
}

std::optional<RecordingRow> RecordingReader::next() {
  std::string line;
  while (std::getline(file_, line)) {
    ++line_;
    if (line.empty() || line == "\r") continue;  // blank lines carry no row
    RecordingRow row;
    row.line = line_;
    const std::vector<std::string> fields = split_fields(line);
    std::string problem = check_row(row, fields);
    ++rows_read_;
    if (!problem.empty()) {
      if (!lenient_) throw InputError(fmt::format("{}:{}: {}", path_, line_, problem));
      row.problem = std::move(problem);
    }
    return row;
  }
  return std::nullopt;
}

std::string RecordingReader::check_row(RecordingRow& row, const std::vector<std::string>& fields) {
  if (fields.size() != column_count_) {
    return fmt::format("expected {} fields, found {}", column_count_, fields.size());
  }
  auto number = [&](std::size_t column, const char* name, double& out) -> std::string {
    const std::optional<double> value = parse_number(fields[column]);
    if (!value) {
      return fmt::format("column {} ({}): '{}' is not a finite number", column + 1, name,
                         fields[column]);
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
                       fields[t_column_], *last_time_);
  }
  last_time_ = row.t_s;
  last_run_ = row.run;
  if (row.voltage_v < kMinVoltageV || row.voltage_v > kMaxVoltageV) {
    return fmt::format("column {} (voltage_v): {} is outside the sensor's range {} to {} V",
                       voltage_column_ + 1, fields[voltage_column_], kMinVoltageV, kMaxVoltageV);
  }
  if (row.temp_c < kMinTempC || row.temp_c > kMaxTempC) {
    return fmt::format("column {} (temp_c): {} is outside the valid range {} to {} C",
                       temp_column_ + 1, fields[temp_column_], kMinTempC, kMaxTempC);
  }
  return "";
}

}  // namespace flange::host
