// SPDX-License-Identifier: MIT
// The recording format every flange command reads: CSV with the header
// t_s,clearance_mm,temp_c,voltage_v and one row per sample, written as it is produced.
// Every number has six decimals (1 us, 1 nm, 1 u-degC, 1 uV, below the ADC's 305 uV LSB), and
// fmt formats them exactly, so a seed gives byte-identical files.
#pragma once

#include <iosfwd>
#include <string>

#include "chain_sample.h"

namespace flange::sim {

inline constexpr const char* kRecordingHeader = "t_s,clearance_mm,temp_c,voltage_v";

class RecordingWriter {
 public:
  // Writes the header line at once.
  explicit RecordingWriter(std::ostream& out);

  // clearance_mm is the reference (micrometer or simulated truth); temp_c and voltage_v are
  // what the DAQ recorded.
  void write(const TrueState& truth, const Reading& reading);

 private:
  std::ostream& out_;
  std::string line_;
};

}  // namespace flange::sim
