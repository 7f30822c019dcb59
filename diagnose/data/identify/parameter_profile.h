// SPDX-License-Identifier: MIT
// The profile of one fitted value (docs/diagnose.md, "What the data can tell"): the value moved
// away from its fit on either side, every other library value refitted so that the fitted voltage
// moves as little as it can, as far as it then moves by no more than the held-out score resolves.
// The values in between are the ones the data allow.
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "effect_classes.h"
#include "twin_replay.h"

namespace flange::diagnose {

// A searched parameter of an effect in a list of modelled effects.
struct ModelledValue {
  std::size_t effect = 0;  // index into the modelled effects
  SearchRange range;
};

// How the replayed voltage on `replay` moves per unit of each value (one column per value, one
// row per sample): central differences a ten-thousandth of the search's width apart, one-sided at
// an edge of the search.
Eigen::MatrixXd value_columns(const TwinReplay& replay,
                              const std::vector<sim::EffectSettings>& modelled,
                              const std::vector<ModelledValue>& values);

// One end of the values the data allow.
struct ProfileEnd {
  double value = 0.0;                          // the moved value there
  std::vector<sim::EffectSettings> modelled{};  // every effect with the others refitted to it
  bool at_edge = false;                        // the end is an edge of the search
};

struct ValueProfile {
  ProfileEnd low, high;
};

// The profile of `values[k]` on `replay`, whose `columns` (value_columns on the same replay) the
// refits step with (Gauss-Newton with the columns held, the other values kept in their searches).
// An end is where the refitted voltage is sqrt(criteria::kScoreResolution) times `noise_v` RMS
// from the fitted one, found from a first step of `resolution` (the linear profile's; the distance
// to the edge where it is infinite), doubled while the refit stays within, then halved between
// the last point within and the first beyond.
ValueProfile profile_value(const TwinReplay& replay,
                           const std::vector<sim::EffectSettings>& modelled,
                           const std::vector<ModelledValue>& values,
                           const Eigen::MatrixXd& columns, std::size_t k, double resolution,
                           double noise_v);

}  // namespace flange::diagnose
