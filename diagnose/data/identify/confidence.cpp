// SPDX-License-Identifier: MIT
#include "confidence.h"

#include <algorithm>

#include "criteria.h"

namespace flange::diagnose {

double confidence_of(const EffectFinding& finding, bool first) {
  const double base = first ? criteria::kFirstClaimAccuracy : criteria::kLaterClaimAccuracy;
  const double alike = 1.0 + static_cast<double>(finding.indistinguishable_from.size());
  const double shared = base * std::clamp(finding.inclusion, 0.0, 1.0) / alike;
  if (finding.indistinguishable_from.empty()) return shared;
  return std::min(shared, criteria::kMostConfidenceOfIndistinguishable);
}

std::vector<EffectFinding> with_confidences(std::vector<EffectFinding> effects) {
  for (std::size_t k = 0; k < effects.size(); ++k) {
    effects[k].confidence = confidence_of(effects[k], k == 0);
  }
  return effects;
}

}  // namespace flange::diagnose
