// SPDX-License-Identifier: MIT
// The blind check on the alternative reality (diagnose/alt_reality/README.md): pairs of bench
// sessions made with formulas that are not the twin's, diagnosed as a user would diagnose two
// recordings (the default twin, noise estimated), and scored by class against the pairs' truth
// afterwards. Nothing here feeds the method: this library links the diagnosis, not the reverse.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "alt_pairs.h"
#include "diagnose_selftest.h"
#include "diagnosis.h"

namespace flange::diagnose {

struct AltScore {
  std::vector<std::string> claimed;  // the classes an "explained" or "partly explained" verdict
                                     // names, in its order
  std::vector<bool> claim_right;     // for each claim, whether the pair holds its class
  std::string nearest;               // "unexplained": the class it came nearest to ("" if none)
  double nearest_shrink_pct = 0.0;   // how far that class alone shrank the held-out gap
  bool verdict_correct = false;      // in-library: explained; null: none; outside: unexplained
  bool top_correct = false;          // in-library: explained, fully or partly, and the first class
                                     // named is a true one
  bool all_found = false;            // in-library: every true class is named
  bool nearest_correct = false;      // in-library and unexplained: the nearest class is a true one
  int spurious = 0;                  // classes named that are not true ones
  bool bias_type = false;            // every true class is a deterministic one (not vibration, ADC)
  double shrink_pct = 0.0;           // held-out gap RMS before -> after the named effects
  double excess_shrink_pct = 0.0;    // the part of it above the pair's true noise
};

// Scores one pair. An "unexplained" verdict's nearest class is the diagnosis's nearest effect
// (the first of `partial` when it gives none).
AltScore score_alt_pair(const alt_reality::AltPairSpec& spec, const Diagnosis& diagnosis,
                        const std::vector<EffectFinding>& partial);

struct AltPairResult {
  alt_reality::AltPairSpec spec;
  Diagnosis diagnosis;
  std::vector<EffectFinding> partial;
  AltScore score;
  double seconds = 0.0;
  std::optional<alt_reality::AltPair> pair;  // kept when a single pair runs (--case)
};

// One row of the table by class: the in-library pairs that hold the class.
struct AltClassRow {
  std::string name;
  int pairs = 0, top_correct = 0, named = 0;
  int bias_pairs = 0;                 // of them, pairs whose every class is bias-type
  double mean_excess_shrink_pct = 0;  // over those
};

struct AltSummary {
  int pairs = 0;
  int in_library = 0, top_correct = 0, all_found = 0, spurious = 0;
  int unexplained_in_library = 0, nearest_correct = 0;
  int partly_explained_in_library = 0, partly_top_correct = 0;
  int bias_type = 0;
  double mean_shrink_pct = 0.0, mean_excess_shrink_pct = 0.0;  // over bias-type pairs
  int null_pairs = 0, null_claims = 0, null_none = 0;
  int outside_pairs = 0, outside_claims = 0, outside_unexplained = 0;
  std::vector<AltClassRow> classes;  // alt_classes() order
  // The aims: >= 95 % right top class, >= 80 % mean shrink of the above-noise gap for
  // bias-type classes, no effect claimed on null or outside pairs, "none" on >= 99 % of nulls.
  bool top_aim_met = false, shrink_aim_met = false, claims_aim_met = false, none_aim_met = false;
  bool aims_met() const { return top_aim_met && shrink_aim_met && claims_aim_met && none_aim_met; }
};
AltSummary summarise_alt_selftest(const std::vector<AltPairResult>& results);

// The UTC time of a session's t_s = 0, as the self-test gives it to the diagnosis (its
// --real-start / --holdout-start): the sensor's age at that instant after a fixed calibration date.
double alt_session_start_utc_s(const alt_reality::SessionPlan& plan);

// A session as `flange diagnose` reads it, with its start time (as a DAQ's file header or a lab
// book gives it; the clock itself restarts at 0 in every session).
RecordingSeries alt_series(const alt_reality::AltRecording& recording,
                           const alt_reality::SessionPlan& plan, const std::string& label);

// Every pair of options.seed (cases = pairs; only_case: just that pair; duration_s > 0 caps the
// sessions), in parallel over options.jobs threads; results in pair order.
std::vector<AltPairResult> run_alt_selftest(const SelftestOptions& options);

}  // namespace flange::diagnose
