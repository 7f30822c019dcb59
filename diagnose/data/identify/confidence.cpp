// SPDX-License-Identifier: MIT
#include "confidence.h"

#include <algorithm>

#include "criteria.h"

namespace flange::diagnose {

double confidence_of(const EffectFinding& finding) {
  const double alike = 1.0 + static_cast<double>(finding.indistinguishable_from.size());
  return criteria::kNamedClassAccuracy * std::clamp(finding.inclusion, 0.0, 1.0) / alike;
}

void set_confidences(Diagnosis& diagnosis) {
  for (EffectFinding& f : diagnosis.effects) f.confidence = confidence_of(f);
}

}  // namespace flange::diagnose
