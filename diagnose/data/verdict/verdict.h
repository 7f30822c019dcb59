// SPDX-License-Identifier: MIT
// The verdict: "explained", "partly explained", "unexplained" or "none", with its reasons
// (docs/diagnose.md, "Verdict"). decide() holds the rules on the figures alone; verdict() gathers
// the figures from the selection and writes the diagnosis.
#pragma once

#include <string>
#include <vector>

#include "diagnosis.h"
#include "findings.h"
#include "locate.h"
#include "parts.h"
#include "selection.h"
#include "signatures.h"
#include "verdict_noise.h"

namespace flange::diagnose {

// The figures the verdict decides on (RMS in V, shares in 0..1).
struct VerdictFigures {
  bool any_findings = false;
  bool gap_exists = false;  // a gap before the picks, or any finding
  // The held-out gap above what an explanation may leave, over the session or in a window, or a
  // stage above its floor where the held-out part does not enter the calibration gap's cell: a
  // gap before any pick.
  bool gap_before_picks = false;
  bool found_by_signature = false;  // a noise-type finding recognised by its signature
  bool picks_alike = false;  // a pick the data cannot tell from another class (confounded)
  double noise_v = 0.0;     // what is left is compared with this (VerdictNoise)
  double rms_before = 0.0, rms_after = 0.0;  // the held-out gap before and after the picks
  double worst_window_v = 0.0;               // the worst window within reach (worst_window)
  double window_allowance_v = 0.0;           // what any one window may hold
  double share_within = 0.0;  // of the held-out samples, within the calibration's ranges
  double within_before_v = 0.0, within_after_v = 0.0;  // the gap there, before and after
  double beyond_share_taken = 0.0;  // of the gap above the noise beyond the ranges, taken
  double within_worst_before_v = 0.0;  // the worst window within reach before the picks
  // Every held-out sample beyond the calibration's ranges lies beyond the ranges an effect of the
  // twin was fitted on (sim::FittedRanges), and there are some.
  bool beyond_past_twin_fits = false;
  // Of the gap above the noise, the share the picks take in the half of the held-out session
  // (by time, first or second) where they take less; a half without a gap above the noise counts
  // 0 (criteria::kPartlyExplainedShareInEachHalf).
  double least_half_share_taken = 1.0;
};

enum class Decision {
  kExplained,
  kExplainedWithinReach,
  kPartlyExplained,
  kUnexplained,
  kNone,
  kNoneWithinTwinFits,
};

// The rules:
// - explained: a finding, and what is left is within criteria::kExplainedRatio of the noise over
//   the session and within the window allowance in every window;
// - explained within reach: what is left is above that over the session but within it on the
//   held-out samples within the calibration's ranges (at least criteria::kLeastShareWithinReach of
//   them, with a gap there above criteria::kGapRatio of the noise) and in every window, and the
//   continued curves take at least the larger of criteria::kLeastShareTakenBeyondReach and the
//   share of samples beyond of the gap above the noise there;
// - partly explained: the picks take at least criteria::kPartlyExplainedShare of the gap above the
//   noise, and at least criteria::kPartlyExplainedShareInEachHalf of it in each half of the
//   held-out session by time;
// - unexplained: a gap exists; none: none does;
// - none, too, where there was no gap before the picks and the picks, none of them found by a
//   signature, take less than criteria::kLeastShareOfNoGapTaken of the gap above the noise: a fit
//   of the noise's residue, not a finding;
// - none within the twin's fits (reported as none), whatever the picks leave: before any pick
//   the gap is within criteria::kExplainedRatio of the noise on the held-out samples within the
//   calibration's ranges (at least criteria::kLeastShareWithinReach of them) and within the
//   window allowance in every window there, and every sample beyond those ranges lies beyond the
//   ranges an effect of the twin was fitted on. There the twin continues its curves as the
//   diagnosis that fitted them said it would ("explained within reach"); data that do not reach
//   further cannot say more. Picks, fitted where the twin leaves only noise, change only how the
//   curves continue there: even where they explain the whole session, they are a guess the
//   held-out part chose among, not a finding (a reason names them).
Decision decide(const VerdictFigures& f);

// The status a decision reports (a scope says "within reach").
Status status_of(Decision decision);

// The verdict stage's value: the diagnosis with its status, scope, findings, nearest effect and
// held-out figures, the held-out figures the report shows, the reasons and, for "unexplained",
// what the candidates did get.
struct VerdictOutcome {
  Diagnosis diagnosis;
  HowFar how_far;
  std::vector<std::string> reasons;
  std::vector<EffectFinding> partial;
};

// The status and the reasons for it, for the diagnosis so far (`so_far`: its stage, clock and
// degenerate data) and the gap located at `where`; `twin_effects` are the effects of the twin the
// recordings are compared with (their fitted ranges, where they carry them).
VerdictOutcome verdict(const Parts& parts, const Selection& selection,
                       const Signatures& signatures, const VerdictNoise& noise,
                       const std::vector<sim::EffectSettings>& twin_effects, const Location& where,
                       Diagnosis so_far);

}  // namespace flange::diagnose
