// SPDX-License-Identifier: MIT
// The blind check of the sim-to-real diagnosis (docs/diagnose.md, "Blind check"). Each case is a
// pair of bench sessions (the thesis's lab protocol through the sensor twin): one to fit on, one
// held out, made the same way with a different noise seed and a slightly different session (room
// temperature, blower timing). A case carries one or two library effects with random parameters,
// or none (null), or an effect outside the library (micrometer backlash, a sudden gain step).
// diagnose() is given the recordings only; the truth is used for scoring afterwards.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "blind_check.h"
#include "diagnosis.h"
#include "effect_catalogue.h"

namespace flange::diagnose {

using SelftestKind = BlindKind;
const char* selftest_kind_name(SelftestKind kind);

// An effect the twin's library does not have, applied by the case generator itself.
struct OutsideEffect {
  std::string name;          // "backlash" (hysteresis of the mount) or "gain_step"
  double value = 0.0;        // backlash: play in mm; gain_step: relative gain change
  double at_fraction = 0.0;  // gain_step: where in each session the step happens, 0..1
  std::string describe() const;
};

struct SelftestCaseSpec {
  int index = 0;  // 1-based
  SelftestKind kind = SelftestKind::kSingle;
  std::vector<sim::EffectSettings> truth;  // library effects switched on (chain order)
  OutsideEffect outside;                   // kOutside only
  std::uint64_t noise_seed = 0;            // the calibration session's; held-out: + 1
};

// Case `index` of a run seeded with `seed`: the kinds cycle through five singles, two pairs, a
// null and two outside-the-library cases (so any 10 consecutive cases hold each kind); effects
// and parameters are drawn at random from the detectable ranges documented in docs/diagnose.md.
SelftestCaseSpec draw_selftest_case(int index, std::uint64_t seed);

struct SelftestRecordings {
  RecordingSeries calibration, heldout;
  double noise_std_v = 0.0;  // the twin's true white noise (for scoring only)
};
// `duration_s` <= 0: the bench protocol's own duration (6600 s).
SelftestRecordings make_selftest_recordings(const SelftestCaseSpec& spec, double duration_s);

// A case's diagnosis against its truth; `noise_std_v`: the twin's true white noise.
using SelftestScore = BlindScore;
SelftestScore score_selftest_case(const SelftestCaseSpec& spec, const Diagnosis& diagnosis,
                                  double noise_std_v);

// The twin's reality for the harness (blind_check.h).
const BlindReality<SelftestCaseSpec, SelftestRecordings>& twin_reality();

// A case run, its recordings kept (sessions) when a single case runs (--case).
using SelftestCaseResult = BlindResult<SelftestCaseSpec, SelftestRecordings>;
// The counts against the twin's aims (>= 90 % correct top effect, >= 70 % mean held-out shrink
// of the gap above the noise for bias-type effects, no effect claimed on a null case).
using SelftestSummary = BlindSummary;
SelftestSummary summarise_selftest(const std::vector<SelftestCaseResult>& results);

// Runs every case (in parallel over `jobs` threads); results in case order.
std::vector<SelftestCaseResult> run_selftest(const SelftestOptions& options);

}  // namespace flange::diagnose
