// SPDX-License-Identifier: MIT
// Everything behind a Diagnosis that diagnosis.json and the report show: the gap at each stage,
// where it lies (operating region, frequency band, time segments), the residual tests, and the
// held-out traces before and after the selected effects.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "diagnosis.h"
#include "findings.h"
#include "improved_twin.h"
#include "locate.h"
#include "twin_noise.h"

namespace flange::diagnose {

// The stages' values side by side: the noise stage's (TwinNoise), the locate stage's
// (Location), how far the picks shrink the held-out gap, what an unexplained verdict's candidates
// got and the verdict's reasons.
struct DiagnosisDetail : TwinNoise, Location {
  // Held-out traces.
  std::vector<double> heldout_t_s, heldout_gap_before_v, heldout_gap_after_v;
  HowFar how_far;
  std::vector<EffectFinding> partial;  // unexplained: what the candidates did get
  std::vector<std::string> reasons;    // why the verdict, one sentence each
};

struct DiagnosisResult {
  Diagnosis diagnosis;
  DiagnosisDetail detail;
  ImprovedTwin improved_twin;  // the twin with the findings added (twin.json)
};

// diagnose() with the detail kept.
DiagnosisResult diagnose_in_detail(const RecordingSeries& calibration,
                                   const RecordingSeries& heldout, const DiagnoseOptions& options);

}  // namespace flange::diagnose
