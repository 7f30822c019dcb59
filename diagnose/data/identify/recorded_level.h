// SPDX-License-Identifier: MIT
// What a law of the temperature is inside the recording: the effect at the calibration part's
// mean temperature, which the data fix even where the law's slope is left open (a gain recorded at
// one temperature is a gain there, whatever it does at 80 degC).
#pragma once

#include <Eigen/Dense>
#include <optional>
#include <vector>

#include "diagnosis.h"
#include "parameter_profile.h"
#include "recording_series.h"

namespace flange::diagnose {

// The level of the effect whose values are `values[k]` for k in `own` (one pick's), when its class
// has one (EffectClass::level): its value at `calibration`'s mean recorded temperature under the
// fitted `modelled`, and its resolution, the change of the level that moves the fitted voltage by
// sqrt(criteria::kScoreResolution) times `noise_v` RMS with every value of `values` free to
// compensate (from their columns' Gram matrix `gram` over `rows` samples; infinite where the level
// moves with a direction of the values the data do not see). Nothing for other classes.
std::optional<EffectLevel> recorded_level(const RecordingSeries& calibration,
                                          const std::vector<sim::EffectSettings>& modelled,
                                          const std::vector<ModelledValue>& values,
                                          const std::vector<std::size_t>& own,
                                          const Eigen::MatrixXd& gram, Eigen::Index rows,
                                          double noise_v);

}  // namespace flange::diagnose
