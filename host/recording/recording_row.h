// SPDX-License-Identifier: MIT
// One row of a recording as the readers return it, and the valid ranges of its quantities.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

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

// Empties `row` for the row on `line`, keeping its strings' storage (no allocation per row).
inline void clear_row(RecordingRow& row, std::size_t line) {
  row.line = line;
  row.t_s = row.temp_c = row.voltage_v = 0.0;
  row.clearance_mm.reset();
  row.run.clear();
  row.problem.clear();
}

// Blank lines carry no row (but count as lines).
inline bool is_blank_line(std::string_view line) { return line.empty() || line == "\r"; }

}  // namespace flange::host
