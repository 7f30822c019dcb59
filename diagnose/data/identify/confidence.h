// SPDX-License-Identifier: MIT
// How far to trust a named class (docs/diagnose.md, "Confidence"): the share of blind claims the
// method gets right in its place in the verdict, the pick's bootstrap inclusion, and the classes
// the data cannot tell from it.
#pragma once

#include <vector>

#include "diagnosis.h"

namespace flange::diagnose {

// Where a class stands in its verdict: the base rate of a claim depends on it.
enum class ClaimPlace { alone, first_of_several, later };

// The base rate of `place` (criteria::kAloneClaimAccuracy, or kAloneCurveOfClearanceClaimAccuracy
// for a class that is a function of the clearance alone; kFirstOfSeveralClaimAccuracy or
// kLaterClaimAccuracy; in a partly explained verdict kPartlyExplainedFirstClaimAccuracy for the
// first or only class, kPartlyExplainedLaterClaimAccuracy for a later one) x inclusion / (1 + the
// classes the data cannot tell from it): how often a class named there is present, lowered where
// resamples of the held-out data do not confirm the class, and shared among the classes the data
// cannot tell apart (each as likely), then at most criteria::kMostConfidenceOfIndistinguishable
// when there are any.
double confidence_of(const EffectFinding& finding, ClaimPlace place, Status status);

// `effects` (a verdict's, in its order) with their confidences; `status` the verdict's.
std::vector<EffectFinding> with_confidences(std::vector<EffectFinding> effects, Status status);

}  // namespace flange::diagnose
