// SPDX-License-Identifier: MIT
// The blind check on the alternative reality (diagnose/alt_reality/README.md): pairs of bench
// sessions made with formulas that are not the twin's, diagnosed as a user would diagnose two
// recordings (the default twin, noise estimated), and scored by class against the pairs' truth
// afterwards, by the harness of the twin's blind check (blind_check.h) with this reality as its
// parameter. Nothing here feeds the method: this library links the diagnosis, not the reverse.
#pragma once

#include <string>
#include <vector>

#include "alt_pairs.h"
#include "blind_check.h"
#include "diagnosis.h"

namespace flange::diagnose {

// A pair's diagnosis against its truth, by class (finding_class.h). An "unexplained" verdict's
// nearest class is the diagnosis's nearest effect (the first of `partial` when it gives none).
using AltScore = BlindScore;
AltScore score_alt_pair(const alt_reality::AltPairSpec& spec, const Diagnosis& diagnosis,
                        const std::vector<EffectFinding>& partial);

// The alternative reality for the harness.
const BlindReality<alt_reality::AltPairSpec, alt_reality::AltPair>& alt_reality_for_check();

// A pair run, its sessions kept when a single pair runs (--case).
using AltPairResult = BlindResult<alt_reality::AltPairSpec, alt_reality::AltPair>;
// One row of the table by class: the in-library pairs that hold the class.
using AltClassRow = BlindClassRow;
// The counts against the aims: >= 95 % right top class, >= 80 % mean shrink of the
// above-noise gap for bias-type classes, no effect claimed on null or outside pairs, "none" on
// >= 99 % of nulls; the rows by class in alt_classes() order.
using AltSummary = BlindSummary;
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
