// SPDX-License-Identifier: MIT
// The sentences of the improved twin (improved_twin/): how it holds each finding, from the
// figures the improved twin hands over, and what was added to the twin.
#pragma once

#include <ostream>
#include <string>

#include "diagnosis.h"
#include "findings.h"

namespace flange::diagnose::reasons {

// diagnosis.json's and twin.json's words for how a finding is held: "library effect", "library
// effect and table", "table", "converter", "white noise", "mount motion", "session's own lines",
// "not held".
const char* held_as_text(HeldAs held);

// The note of each way a finding is held, from its figures.
std::string held_in_white_noise(double lsb_v);
std::string held_as_converter(bool with_daq_gain);
std::string held_as_mount_motion(double rms_mm);
// Lines of each session: a free shape of the lines held as one line of `rms_v` at `mains_hz`, or
// the library effect.
std::string held_as_one_session_line(double rms_v, double mains_hz);
std::string held_as_session_lines_effect();
std::string not_held_in_table(double misfit_v, double allowed_v);
std::string held_as_member_and_table(double misfit_v);
std::string held_in_table(double misfit_v);
std::string held_as_library_effect();

// The improved twin's summary: the findings added with the verdict and the white noise, or the
// white noise alone when the verdict selects none.
std::string improved_twin_summary(std::size_t findings, Status status, double noise_v);
// A twin note for a finding the twin cannot hold.
std::string not_held_note(const std::string& name, const std::string& why);

}  // namespace flange::diagnose::reasons
