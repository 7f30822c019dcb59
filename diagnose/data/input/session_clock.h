// SPDX-License-Identifier: MIT
// How the two sessions' clocks relate (docs/diagnose.md, "Sessions and time").
#pragma once

#include <string>

#include "recording_series.h"

namespace flange::diagnose {

// How much later the held-out session's t_s = 0 is than the calibration's, and how that is known:
// "start times" (both sessions' starts given), "one clock" (the held-out times continue the
// calibration part's) or "unknown" (the held-out clock restarts and no start times: each session
// is taken to start at the same age).
struct SessionClock {
  std::string kind;           // Diagnosis::clock
  double age_offset_s = 0.0;  // 0 unless the start times say otherwise
  bool heldout_age_unknown() const { return kind == "unknown"; }
};

SessionClock session_clock(const RecordingSeries& calibration, const RecordingSeries& heldout);

}  // namespace flange::diagnose
