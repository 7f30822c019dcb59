// SPDX-License-Identifier: MIT
// The null replicas of a twin that holds what the noiseless replay cannot stand for: mount motion
// (each session's own random motion, drawn afresh for every replica) or the converter (whose
// rounding comes after the analog noise). null_replicas.h draws them.
#pragma once

#include "diagnosis.h"
#include "null_replicas.h"
#include "twin_replay.h"
#include "white_noise.h"

namespace flange::diagnose {

// The replicas of the twin of `given` on `replay`: a fresh draw of the motion, the analog noise
// of `white`, then the converter the twin holds (or the recording's grid); unset when it holds
// neither. `replay` and `white` must outlive it.
NullReplica null_replica(const TwinReplay& replay, const DiagnoseOptions& given,
                         const WhiteNoise& white);

}  // namespace flange::diagnose
