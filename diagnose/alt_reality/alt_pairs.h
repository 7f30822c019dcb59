// SPDX-License-Identifier: MIT
// Pairs of bench sessions of the alternative reality, as `flange diagnose --real A --holdout B`
// takes them: a fitting session and a held-out one, days later on the same bench (same family
// of protocols, other parameters), both clocks starting at 0. A pair holds effects of one or two
// classes, none (null) or one outside the library; its truth is kept apart from the recordings.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "alt_effect.h"
#include "alt_session.h"

namespace flange::alt_reality {

enum class AltPairKind { kSingle, kDouble, kNull, kOutside };
const char* alt_pair_kind_name(AltPairKind kind);

struct TruthEffect {
  AltEffectDraw draw;  // class, shape and every parameter as rendered
  double rms_v = 0.0;  // its noise-free RMS on the fitting session, alone, V
};

struct AltPairSpec {
  int index = 0;  // 1-based
  std::uint64_t seed = 0;
  AltPairKind kind = AltPairKind::kNull;
  std::vector<TruthEffect> truth;  // in chain order; an outside effect has class "outside"
  SessionPlan fit, heldout;
};

// Pair `index` of the run seeded `seed`. Kinds cycle over every 10 pairs: six singles, a double,
// a null, an outside, a null; the singles take the eleven classes in turn (from a class set by
// the seed), so any 110 pairs hold every class six times. The noise is drawn log-uniform in
// 0.01-0.1 V. Each effect is sized on the fitting session by the RMS of what it adds to the gap
// an ideal twin sees (recorded voltage less the ideal sensor's at the recorded clearance and
// temperature, noise off): shapes with an amplitude are scaled to 1 to 5 times the noise
// (log-uniform); others (lags, skews, compression) are redrawn, up to ten times, until they
// reach the noise, and if even the largest stays below it the pair's noise is lowered to it
// (not below 0.01 V); converters and dropouts are taken as drawn. `duration_s` > 0 caps both
// sessions' length (the protocols' own are 3600-6600 s).
AltPairSpec draw_alt_pair(int index, std::uint64_t seed, double duration_s = 0.0);

struct AltPair {
  AltRecording fit, heldout;
};
AltPair render_alt_pair(const AltPairSpec& spec);

}  // namespace flange::alt_reality
