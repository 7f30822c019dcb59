// SPDX-License-Identifier: MIT
// A candidate effect of one round: fitted on the calibration part, scored on the held-out part.
#pragma once

#include <optional>
#include <vector>

#include "effect_catalogue.h"
#include "effect_fit.h"
#include "free_shape_fit.h"

namespace flange::diagnose {

struct Candidate {
  EffectFit fit;
  std::vector<sim::EffectSettings> with;  // modelled + the candidate, refitted
  std::vector<double> heldout_error;      // the held-out gap `with` leaves
  // A free-shape candidate (free_shape_fit.h): its curve, added to the voltage beside `with`
  // (then the modelled effects as they were).
  std::optional<FreeShapeFit> free_shape;
};

// How many values a candidate's calibration fit chose.
int free_values_of(const Candidate& c);

}  // namespace flange::diagnose
