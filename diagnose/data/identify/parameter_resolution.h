// SPDX-License-Identifier: MIT
// What the data tell of each pick's parameters (docs/diagnose.md, "What the data can tell"): a
// parameter's resolution is how far it moves, with every other fitted value compensating, before
// the calibration part's fitted voltage moves by more than the held-out score resolves; the values
// its profile allows (parameter_profile.h) leave it undetermined when they change the twin outside
// the recording, over the bench's operating range, by more than the verdict would call explained,
// or reach both edges of its search, and a bound when they reach one edge.
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "effect_classes.h"
#include "parameter_profile.h"
#include "parts.h"
#include "selection.h"
#include "twin_replay.h"

namespace flange::diagnose {

// The change of a value that moves the fitted voltage by sqrt(criteria::kScoreResolution) times
// the noise `noise_v` (RMS), for a compensated sensitivity of `sensitivity` V per unit (infinite
// at 0): a mean-square change of kScoreResolution sigma^2, what the selection's ties cannot order.
double resolution_of(double sensitivity, double noise_v);

// The noise resolutions are judged against: the selection's, at least
// criteria::kTieFloorShareOfGap of the held-out gap's RMS before the picks.
double resolution_noise(const Selection& selection);

// What the data say of one library value.
struct ValueJudgement {
  bool undetermined = false;
  std::string bound{};  // "<= x" or ">= x" where the allowed values reach one edge of the search
};

// `values[k]` for each k of `which`, judged on `replay` (the calibration part, or a session that
// was not recorded; its search rows, TwinReplay::search_replay): the values its profile allows,
// from its linear resolution at `noise_v`, are undetermined when they reach both edges of its
// search or change the twin's voltage on `operating_range` (a replay of operating_range_session)
// by more than criteria::kMostChangeOutsideTheRecording times `noise_v` RMS; else a bound where
// they reach one edge. One judgement per entry of `which`.
std::vector<ValueJudgement> judge_values(const TwinReplay& replay,
                                         const TwinReplay& operating_range,
                                         const std::vector<sim::EffectSettings>& modelled,
                                         const std::vector<ModelledValue>& values,
                                         const std::vector<std::size_t>& which, double noise_v);

// The selection with every pick's finding given each fitted value's resolution, the undetermined
// ones, the bounds and, for a class with a law of the temperature, its level at the calibration
// part's mean temperature (recorded_level.h). A library pick's values are its class's searched
// parameters, their resolutions from the replayed voltage's central differences on the
// calibration part, compensated by every library pick's parameters at once, and judged by
// judge_values. A free shape's values are its curve's, their sensitivities its own columns'
// (FreeShapeFit); undetermined when the resolution exceeds the largest value the curve takes (a
// free shape does not extrapolate); a value its family searched on a bounded range (a ripple's
// period, a settling time) that ended on an edge of it is a bound.
Selection resolve_parameters(const Parts& parts, Selection selection);

}  // namespace flange::diagnose
