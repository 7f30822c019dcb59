// SPDX-License-Identifier: MIT
// The two parts of the data a diagnosis reads, each with the twin replayed on its inputs, and
// what every stage after the replay shares.
#pragma once

#include <optional>

#include "adc_grid.h"
#include "diagnosis.h"
#include "recorded_part.h"
#include "twin_replay.h"

namespace flange::diagnose {

struct Parts {
  const RecordingSeries& calibration;
  const RecordingSeries& heldout;
  TwinReplay cal_replay;
  TwinReplay ho_replay;
  bool heldout_age_unknown;     // the sessions' clocks are unknown (SessionClock "unknown")
  std::optional<AdcGrid> grid;  // the converter grid both parts lie on (shared_grid), if one

  RecordedPart cal() const { return {calibration, cal_replay}; }
  RecordedPart ho() const { return {heldout, ho_replay}; }
};

// Both parts replayed on the twin of `options` (the held-out part `clock.age_offset_s` older),
// with the converter grid they share: the replays and the grid search run at once, since each
// inverts or scans a whole record.
Parts replay_parts(const RecordingSeries& calibration, const RecordingSeries& heldout,
                   const DiagnoseOptions& options, double age_offset_s, bool heldout_age_unknown);

}  // namespace flange::diagnose
