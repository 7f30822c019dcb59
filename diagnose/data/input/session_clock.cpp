// SPDX-License-Identifier: MIT
#include "session_clock.h"

namespace flange::diagnose {

SessionClock session_clock(const RecordingSeries& calibration, const RecordingSeries& heldout) {
  if (calibration.start_utc_s && heldout.start_utc_s) {
    return {"start times", *heldout.start_utc_s - *calibration.start_utc_s};
  }
  if (heldout.t_s.front() > calibration.t_s.back()) return {"one clock", 0.0};
  return {"unknown", 0.0};
}

}  // namespace flange::diagnose
