// SPDX-License-Identifier: MIT
#include "recording_writer.h"

#include <fmt/format.h>

#include <iterator>
#include <ostream>

namespace flange::sim {

RecordingWriter::RecordingWriter(std::ostream& out) : out_(out) {
  out_ << kRecordingHeader << '\n';
}

void RecordingWriter::write(const TrueState& truth, const Reading& reading) {
  line_.clear();
  fmt::format_to(std::back_inserter(line_), "{:.6f},{:.6f},{:.6f},{:.6f}\n", truth.t_s,
                 truth.clearance_mm, reading.temp_c, reading.voltage_v);
  out_.write(line_.data(), static_cast<std::streamsize>(line_.size()));
}

}  // namespace flange::sim
