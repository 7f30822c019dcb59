// SPDX-License-Identifier: MIT
// The gap at each stage of the chain (voltage, compensated clearance, filtered clearance, alarm
// timing) against what the twin's noise alone gives there.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "findings.h"
#include "null_replicas.h"
#include "polynomial_sensor_model.h"
#include "recording_series.h"
#include "white_noise.h"

namespace flange::diagnose {

// Each stage's gap of `real` against the twin's voltage `sim_v`, with its noise floor: the median
// of the null replicas' (their spread is a few per cent) or, for alarm timing, their largest.
// A stage is significant above criteria::kStageSignificanceRatio times its floor (alarm timing:
// AlarmTiming::exceeds). The replicas are drawn by `replica_of` when set (null_replicas.h).
std::vector<StageGap> stage_gaps(const RecordingSeries& real, const std::vector<double>& sim_v,
                                 const WhiteNoise& white, const sim::PolynomialSensorModel& model,
                                 double fs_hz, std::uint64_t seed,
                                 const NullReplica& replica_of = {});

// The first stage whose gap stands above its noise floor; empty when none does.
std::string first_significant_stage(const std::vector<StageGap>& stages);

}  // namespace flange::diagnose
