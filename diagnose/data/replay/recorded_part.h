// SPDX-License-Identifier: MIT
// A part of the recording (the calibration part or the held-out one) with the twin replayed on
// it: what a fit reads of one part.
#pragma once

#include "recording_series.h"
#include "twin_replay.h"

namespace flange::diagnose {

struct RecordedPart {
  const RecordingSeries& series;
  const TwinReplay& replay;
  // The part placed this much older than its replay's age offset says (the held-out session's
  // place in the sensor's age, where its clock does not say it).
  double age_shift_s = 0.0;
};

}  // namespace flange::diagnose
