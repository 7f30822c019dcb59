// SPDX-License-Identifier: MIT
// A part of the recording with the twin replayed on its inputs: what every stage reads.
#pragma once

#include "recording_series.h"
#include "twin_replay.h"

namespace flange::diagnose {

struct RecordedPart {
  const RecordingSeries& series;
  const TwinReplay& replay;
  double age_shift_s = 0.0;  // the part placed this much older than its replay's age offset says
};

}  // namespace flange::diagnose
