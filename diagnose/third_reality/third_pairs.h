// SPDX-License-Identifier: MIT
// Pairs of bench sessions of the third reality, as `flange diagnose --real A --holdout B` takes
// them: a fitting session and a held-out one, days later on the same bench (the same kinds of
// heating and micrometer protocol, other parameters), both clocks starting at 0. A pair holds one
// to three effects of the library's classes, none (null) or one outside the library; its truth is
// kept apart from the recordings.
#pragma once

#include <cstdint>
#include <vector>

#include "third_effect.h"
#include "third_session.h"

namespace flange::third_reality {

enum class ThirdPairKind { kSingle, kMulti, kNull, kOutside };
const char* third_pair_kind_name(ThirdPairKind kind);

struct ThirdTruthEffect {
  EffectDraw draw;     // class, shape and every parameter as rendered
  double rms_v = 0.0;  // what it alone adds to the gap an ideal twin sees, noise-free, fitting
                       // session, RMS, V
};

struct ThirdPairSpec {
  int index = 0;  // 1-based
  std::uint64_t seed = 0;
  ThirdPairKind kind = ThirdPairKind::kNull;
  std::vector<ThirdTruthEffect> truth;  // in chain order; an outside effect has class "outside"
  SessionPlan fit, heldout;
};

// The smallest and largest size of an effect, as its RMS over the pair's noise.
inline constexpr double kLeastSize = 1.2;
inline constexpr double kMostSize = 2.0;

// Pair `index` (1-based) of the run seeded `seed`. Kinds cycle over every 10 pairs: four
// singles, two pairs of two classes, one of three, a null, an outside effect, a null; the singles
// take the eleven classes in turn (from a class set by the seed); the classes of a multiple pair
// are drawn at random, at most one of them sized by the noise. Rates 6, 7, 8, 9 or 10 Hz (three
// pairs in five) or 12.5, 20, 25, 50 or 100 Hz, one where the mains shows as a line when the pair
// holds mains pick-up. Every effect alone adds 1.2-2 times the pair's noise (drawn uniformly) to
// the gap an ideal twin sees on the fitting session: an amplitude is scaled to it, and a lagging
// reading or a converter, which have none, set the noise (0.002-0.1 V) instead. `duration_s` > 0
// caps both sessions' length (the protocols' own are 2400-5400 s).
ThirdPairSpec draw_third_pair(int index, std::uint64_t seed, double duration_s = 0.0);

struct ThirdPair {
  ThirdRecording fit, heldout;
};
ThirdPair render_third_pair(const ThirdPairSpec& spec);

}  // namespace flange::third_reality
