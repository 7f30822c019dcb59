// SPDX-License-Identifier: MIT
// Lines each session has of its own: the mains' phase at a session's start is arbitrary, and with
// a grid whose frequency wanders so is their amplitude from window to window. A twin that holds
// such a class (EffectClass::lines_of_each_session) cannot replay them on another session. A
// diagnosis against it takes each part's own lines out of its recording instead, fitted by the
// class's free shape to the gap the twin's other effects leave there, and diagnoses what is left.
#pragma once

#include <optional>
#include <string>

#include "diagnosis.h"
#include "recording_series.h"

namespace flange::diagnose {

// The two recordings less their own lines, and the twin without the classes that made them.
struct SessionLines {
  RecordingSeries calibration, heldout;
  DiagnoseOptions options;
  std::string reason;  // one sentence for the verdict's reasons: what was taken out
};

// Nothing when the twin of `options` holds no class with lines of each session; the sessions'
// clocks place the held-out part as the diagnosis does (`age_offset_s`).
std::optional<SessionLines> take_out_session_lines(const RecordingSeries& calibration,
                                                   const RecordingSeries& heldout,
                                                   const DiagnoseOptions& options,
                                                   double age_offset_s, bool heldout_age_unknown);

}  // namespace flange::diagnose
