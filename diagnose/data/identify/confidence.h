// SPDX-License-Identifier: MIT
// How far to trust a named class (docs/diagnose.md, "Confidence"): the share of blind self-test
// claims the method gets right, the pick's bootstrap inclusion, and the classes the data cannot
// tell from it.
#pragma once

#include "diagnosis.h"

namespace flange::diagnose {

// criteria::kNamedClassAccuracy x inclusion / (1 + the classes the data cannot tell from it): the
// base rate at which a named class is present, lowered where resamples of the held-out data do
// not confirm the pick and shared among the classes the data cannot tell apart (each as likely).
double confidence_of(const EffectFinding& finding);

// Every named effect's confidence.
void set_confidences(Diagnosis& diagnosis);

}  // namespace flange::diagnose
