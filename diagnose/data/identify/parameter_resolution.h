// SPDX-License-Identifier: MIT
// What the data tell of each pick's parameters (docs/diagnose.md, "What the data can tell"): a
// parameter is determined when moving it, with every other fitted value compensating, moves the
// calibration part's fitted voltage by more than the held-out score resolves; one the data
// cannot tell across most of its search is undetermined; one whose value the data cannot tell
// from an edge of its search is a bound.
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "effect_classes.h"
#include "parts.h"
#include "selection.h"
#include "twin_replay.h"

namespace flange::diagnose {

// A searched parameter of an effect in a list of modelled effects.
struct ModelledValue {
  std::size_t effect = 0;  // index into the modelled effects
  SearchRange range;
};

// Each value's compensated sensitivity on `replay` (V RMS per unit, compensated_sensitivity.h):
// the replayed voltage's central differences (one-sided at an edge of the search), a
// ten-thousandth of the search's width apart, compensated by every other value listed.
Eigen::VectorXd value_sensitivity(const TwinReplay& replay,
                                  const std::vector<sim::EffectSettings>& modelled,
                                  const std::vector<ModelledValue>& values);

// Whether the values within `resolution` of `at` cover criteria::kUndeterminedShareOfSearch of
// `range`.
bool undetermined_within(const SearchRange& range, double at, double resolution);

// The change of a value that moves the fitted voltage by sqrt(criteria::kScoreResolution) times
// the noise `noise_v` (RMS), for a compensated sensitivity of `sensitivity` V per unit (infinite
// at 0): a mean-square change of kScoreResolution sigma^2, what the selection's ties cannot order.
double resolution_of(double sensitivity, double noise_v);

// The noise resolutions are judged against: the selection's, at least
// criteria::kTieFloorShareOfGap of the held-out gap's RMS before the picks.
double resolution_noise(const Selection& selection);

// The selection with every pick's finding given each fitted value's resolution, the undetermined ones and the
// bounds. A library pick's values are its class's searched parameters, their sensitivities the
// replayed voltage's central differences on the calibration part, compensated by every library
// pick's parameters at once; undetermined when the values the data cannot tell from the fitted
// one cover criteria::kUndeterminedShareOfSearch of the search range, a bound when they reach an
// edge. A free shape's values are its curve's, their sensitivities its own columns' (FreeShapeFit);
// undetermined when the resolution exceeds the largest value the curve takes; a value its family
// searched on a bounded range (a ripple's period, a settling time) that ended on an edge of it is
// a bound.
Selection resolve_parameters(const Parts& parts, Selection selection);

}  // namespace flange::diagnose
