// SPDX-License-Identifier: MIT
// The alarm-timing stage: when the alarms of the recorded and the twin's filtered clearance change
// level, and how far apart. Its floor is the largest of the null replicas' gaps (a largest onset
// difference jumps to the time to the next alarm change when noise makes or misses one, so the
// median would not bound it), which a noise-made gap passes with odds of 1 in
// criteria::kNullReplicas + 1: so it must show on the held-out part too (against that part's own
// replicas) to count, and a null pair passes both about 1 time in 1,000.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "diagnosis.h"
#include "findings.h"
#include "null_replicas.h"
#include "thresholds.h"
#include "white_noise.h"

namespace flange::diagnose {

struct AlarmChange {
  double t_s;
  host::AlarmLevel level;
};

// The alarm changes of a filtered clearance at times `t`, through the host's default thresholds.
std::vector<AlarmChange> alarm_changes(const std::vector<double>& t,
                                       const std::vector<double>& clearance);

// Largest time between a change in `a` and the nearest change to the same level in `b`, both
// ways; a change with no partner counts as the record's length.
double alarm_timing_gap(const std::vector<AlarmChange>& a, const std::vector<AlarmChange>& b,
                        double record_s);

struct AlarmTiming {
  double gap_s = 0.0, floor_s = 0.0;
  std::size_t real_changes = 0, sim_changes = 0;
  bool exceeds() const;  // gap_s > floor_s + criteria::kAlarmMarginS
};

// The alarm-timing gap of `real` (its filtered clearance `f_real`) against the twin's alarm
// changes `a_sim`, and its floor, the largest of the null replicas' (`alarm_floor`).
AlarmTiming alarm_timing(const RecordingSeries& real, const std::vector<double>& f_real,
                         const std::vector<AlarmChange>& a_sim,
                         const std::vector<double>& alarm_floor);

// The alarm-timing stage counts only when the held-out part shows it too: a stage that the
// calibration part alone exceeds is kept, not significant, with the held-out figures in its note.
// Its floor's replicas are drawn by `replica_of` when set (null_replicas.h).
// Returns `stages` with the alarm-timing stage confirmed or not.
std::vector<StageGap> confirm_alarm_timing_on_heldout(const RecordingSeries& heldout,
                                                      const std::vector<double>& ho_sim_v,
                                                      const DiagnoseOptions& options,
                                                      const WhiteNoise& white, double fs_hz,
                                                      std::vector<StageGap> stages,
                                                      const NullReplica& replica_of = {});

}  // namespace flange::diagnose
