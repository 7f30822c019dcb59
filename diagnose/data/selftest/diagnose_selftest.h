// SPDX-License-Identifier: MIT
// The blind check of the sim-to-real diagnosis (docs/diagnose.md, "Blind check"). Each case is a
// pair of bench sessions (the thesis's lab protocol through the sensor twin): one to fit on, one
// held out, made the same way with a different noise seed and a slightly different session (room
// temperature, blower timing). A case carries one or two library effects with random parameters,
// or none (null), or an effect outside the library (micrometer backlash, a sudden gain step).
// diagnose() is given the recordings only; the truth is used for scoring afterwards.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "diagnosis.h"
#include "effect_catalogue.h"

namespace flange::diagnose {

enum class SelftestKind { kSingle, kPair, kNull, kOutside };
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

struct SelftestScore {
  std::vector<std::string> claimed;  // effects the verdict names (explained, fully or partly)
  std::vector<bool> claim_right;     // for each claim, whether its effect is in the truth
  bool verdict_correct = false;      // in-library: explained; null: none; outside: unexplained
  bool top_correct = false;          // in-library: the first named effect is a true one
  bool all_found = false;            // in-library: every true effect is named
  int spurious = 0;                  // named effects that are not true ones
  bool bias_type = false;            // every true effect is removable (all but vibration, ADC)
  double shrink_pct = 0.0;           // held-out gap RMS, before -> after the named effects
  double excess_shrink_pct = 0.0;    // the part of the held-out gap RMS above the noise
};
SelftestScore score_selftest_case(const SelftestCaseSpec& spec, const Diagnosis& diagnosis,
                                  double noise_std_v);

struct SelftestCaseResult {
  SelftestCaseSpec spec;
  Diagnosis diagnosis;
  std::vector<EffectFinding> partial;  // unexplained: what the candidates did get
  SelftestScore score;
  double seconds = 0.0;                          // recording plus diagnosis
  std::optional<SelftestRecordings> recordings;  // kept when a single case runs (--case)
};

struct SelftestSummary {
  int cases = 0;
  int in_library = 0, top_correct = 0, all_found = 0, spurious = 0;
  int bias_type = 0;
  double mean_shrink_pct = 0.0, mean_excess_shrink_pct = 0.0;  // over bias-type cases
  int null_cases = 0, null_claims = 0, null_correct = 0;
  int outside_cases = 0, outside_claims = 0, outside_correct = 0;
  // Aims of the issue: >= 90 % correct top effect, >= 70 % mean held-out shrink (of the gap
  // above the noise) for bias-type effects, no effect claimed on a null case.
  bool top_aim_met = false, shrink_aim_met = false, null_aim_met = false;
  bool aims_met() const { return top_aim_met && shrink_aim_met && null_aim_met; }
};
SelftestSummary summarise_selftest(const std::vector<SelftestCaseResult>& results);

struct SelftestOptions {
  int cases = 10;
  int only_case = 0;  // > 0: run just this case of the seed (to look into one row of a table)
  std::uint64_t seed = 1;
  double duration_s = 0.0;     // <= 0: the protocol's own
  int bootstrap_rounds = 100;  // passed to diagnose()
  int jobs = 0;                // worker threads; 0: the machine's cores
};
// Runs every case (in parallel over `jobs` threads); results in case order.
std::vector<SelftestCaseResult> run_selftest(const SelftestOptions& options);

}  // namespace flange::diagnose
