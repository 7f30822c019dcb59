// SPDX-License-Identifier: MIT
#include "confidence.h"

#include <algorithm>

#include "criteria.h"

namespace flange::diagnose {

double confidence_of(const EffectFinding& finding, bool first) {
  const double base = first ? criteria::kFirstClaimAccuracy : criteria::kLaterClaimAccuracy;
  const double alike = 1.0 + static_cast<double>(finding.indistinguishable_from.size());
  return base * std::clamp(finding.inclusion, 0.0, 1.0) / alike;
}

void set_confidences(Diagnosis& diagnosis) {
  for (std::size_t k = 0; k < diagnosis.effects.size(); ++k) {
    diagnosis.effects[k].confidence = confidence_of(diagnosis.effects[k], k == 0);
  }
}

}  // namespace flange::diagnose
