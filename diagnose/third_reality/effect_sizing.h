// SPDX-License-Identifier: MIT
// Drawing a pair's effects at their sizes: each effect alone adds kLeastSize-kMostSize times the
// pair's noise (drawn uniformly) to the gap an ideal twin sees on the noise-free fitting session.
// An effect with an amplitude is scaled to that (a few passes for one not linear in it: a skew,
// a vibration, a backlash); an effect without one (a lagging reading, a converter) sets the
// pair's noise instead, redrawn until that noise lies in 0.002-0.1 V.
#pragma once

#include <string>
#include <vector>

#include "third_classes.h"
#include "third_pairs.h"

namespace flange::third_reality {

// What a draw may depend on, from the pair's noise-free fitting session without effects and the
// held-out session's end.
DrawContext draw_context(const SessionPlan& fit, const SessionPlan& heldout);

// The effects of `classes` (at most one that sets the noise), drawn and sized on `spec`'s
// sessions; sets spec.fit.noise_v and spec.heldout.noise_v when one sets the noise.
std::vector<ThirdTruthEffect> sized_effects(const std::vector<std::string>& classes,
                                            ThirdPairSpec& spec, ThirdRandom& random);

}  // namespace flange::third_reality
