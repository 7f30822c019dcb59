// SPDX-License-Identifier: MIT
// The free-shape candidates of a round: each family of a class not yet modelled fitted by least
// squares to the gap the modelled effects leave (no refit of the others), scored on held-out data.
#pragma once

#include <vector>

#include "candidate.h"
#include "recorded_part.h"

namespace flange::diagnose {

// What a round's free shapes are fitted to: the parts (as the coil sees them behind a modelled
// channel delay: replay/coil_parts.h), the gaps the modelled effects leave on each, the effects
// modelled, and whether the held-out session's age is unknown.
struct FreeShapeRound {
  RecordedPart calibration, heldout;
  const std::vector<double>& cal_gap_v;
  const std::vector<double>& ho_gap_v;
  const std::vector<sim::EffectSettings>& modelled;
  bool heldout_age_unknown = false;
  bool no_level_carried = false;  // FreeShapeInputs::no_level_carried
};

// `family` fitted on `round` as a candidate: named by the class the fitted shape names (a
// compression whose knee does not move is a static nonlinearity), its held-out error the
// held-out gap less its curve.
Candidate free_shape_candidate(const FreeShapeFamily& family, const FreeShapeRound& round);

// The candidates of `families`, each fitted in its own thread and taken in their order (the
// families that took longest last time started first: longest_first.h).
std::vector<Candidate> free_shape_candidates(const std::vector<FreeShapeFamily>& families,
                                             const FreeShapeRound& round);

}  // namespace flange::diagnose
