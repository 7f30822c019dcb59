// SPDX-License-Identifier: MIT
// The blind check on the third reality (diagnose/third_reality/README.md): pairs of bench
// sessions whose effects follow what they follow with shapes drawn at random, one to three at a
// time, diagnosed as a user would diagnose two recordings (the default twin, noise estimated),
// and scored by class against the pairs' truth afterwards by the blind-check harness
// (blind_check.h), with class_of_finding (finding_class.h) naming the findings. Nothing here
// feeds the method: this library links the diagnosis, not the reverse.
#pragma once

#include <string>
#include <vector>

#include "blind_check.h"
#include "diagnosis.h"
#include "third_pairs.h"

namespace flange::diagnose {

BlindScore score_third_pair(const third_reality::ThirdPairSpec& spec, const Diagnosis& diagnosis,
                            const std::vector<EffectFinding>& partial);

const BlindReality<third_reality::ThirdPairSpec, third_reality::ThirdPair>&
third_reality_for_check();

using ThirdPairResult = BlindResult<third_reality::ThirdPairSpec, third_reality::ThirdPair>;
BlindSummary summarise_third_selftest(const std::vector<ThirdPairResult>& results);

// The UTC time of a session's t_s = 0 as the self-test gives it to the diagnosis: the sensor's
// age at that instant after a fixed calibration date.
double third_session_start_utc_s(const third_reality::SessionPlan& plan);

RecordingSeries third_series(const third_reality::ThirdRecording& recording,
                             const third_reality::SessionPlan& plan, const std::string& label);

// Every pair of options.seed (cases = pairs; only_case: just that pair; duration_s > 0 caps the
// sessions), in parallel over options.jobs threads; results in pair order.
std::vector<ThirdPairResult> run_third_selftest(const SelftestOptions& options);

// The aims on the third reality, each against its own share: the right class first on
// >= 95 % of single-effect pairs and >= 90 % of two- and three-effect pairs, every true class
// named on >= 85 % of the latter, nothing claimed on >= 95 % of null and outside pairs, and a
// mean held-out shrink of the gap above the noise >= 80 % on explained bias-type pairs.
struct ThirdAims {
  int singles = 0, singles_top = 0;
  int multiples = 0, multiples_top = 0, multiples_all = 0;
  // The same counts where a finding stands for the classes it cannot be told from too
  // (BlindScore::top_among_indistinguishable): reported beside the aims, not in them.
  int singles_top_among = 0, multiples_top_among = 0, multiples_all_among = 0;
  int controls = 0, controls_quiet = 0;  // null and outside pairs; those that claim nothing
  int explained_bias = 0;
  double explained_excess_shrink_pct = 0.0;
  bool singles_met = false, multiples_top_met = false, multiples_all_met = false;
  bool controls_met = false, shrink_met = false;
  bool met() const {
    return singles_met && multiples_top_met && multiples_all_met && controls_met && shrink_met;
  }
};
ThirdAims third_aims(const BlindSummary& summary);

}  // namespace flange::diagnose
