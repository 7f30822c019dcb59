// SPDX-License-Identifier: MIT
#include "confidence.h"

#include <algorithm>

#include "criteria.h"
#include "effect_classes.h"

namespace flange::diagnose {

namespace {

// A class that is a function of the clearance alone, named alone, has a base rate of its own
// (criteria::kAloneCurveOfClearanceClaimAccuracy); so do the classes of a partly explained verdict,
// which leaves part of the gap to something none of them models.
double base_rate(const EffectFinding& finding, ClaimPlace place, Status status) {
  if (status == Status::kPartlyExplained) {
    return place == ClaimPlace::later ? criteria::kPartlyExplainedLaterClaimAccuracy
                                      : criteria::kPartlyExplainedFirstClaimAccuracy;
  }
  const EffectClass* effect = find_effect_class(finding.name);
  const bool curve_of_clearance = effect != nullptr && effect->function_of_clearance_alone;
  switch (place) {
    case ClaimPlace::alone:
      return curve_of_clearance ? criteria::kAloneCurveOfClearanceClaimAccuracy
                                : criteria::kAloneClaimAccuracy;
    case ClaimPlace::first_of_several: return criteria::kFirstOfSeveralClaimAccuracy;
    case ClaimPlace::later: return criteria::kLaterClaimAccuracy;
  }
  return criteria::kLaterClaimAccuracy;
}

}  // namespace

double confidence_of(const EffectFinding& finding, ClaimPlace place, Status status) {
  const double base = base_rate(finding, place, status);
  const double alike = 1.0 + static_cast<double>(finding.indistinguishable_from.size());
  const double shared = base * std::clamp(finding.inclusion, 0.0, 1.0) / alike;
  if (finding.indistinguishable_from.empty()) return shared;
  return std::min(shared, criteria::kMostConfidenceOfIndistinguishable);
}

std::vector<EffectFinding> with_confidences(std::vector<EffectFinding> effects, Status status) {
  for (std::size_t k = 0; k < effects.size(); ++k) {
    const ClaimPlace place = k > 0                ? ClaimPlace::later
                             : effects.size() == 1 ? ClaimPlace::alone
                                                   : ClaimPlace::first_of_several;
    effects[k].confidence = confidence_of(effects[k], place, status);
  }
  return effects;
}

}  // namespace flange::diagnose
