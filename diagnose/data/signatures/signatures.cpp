// SPDX-License-Identifier: MIT
#include "signatures.h"

#include <algorithm>
#include <cmath>

#include "series_statistics.h"

namespace flange::diagnose {

std::vector<EffectFinding> findings_of(const Selection& selection, const Signatures& signatures) {
  std::vector<EffectFinding> findings;
  for (const Pick& pick : selection.picks) findings.push_back(pick.finding);
  if (signatures.quantisation) {
    // Each pick takes sqrt(before^2 - after^2) of the held-out gap's RMS; the converter's size is
    // what its rounding puts in the gap, which the grid itself shows whether or not the twin's
    // converter reproduces the codes.
    const double rounding_rms = signatures.quantised_on->lsb_v / std::sqrt(12.0);
    const auto smaller =
        std::find_if(findings.begin(), findings.end(), [&](const EffectFinding& f) {
          return rms_above_noise(f.heldout_rms_before, f.heldout_rms_after) < rounding_rms;
        });
    findings.insert(smaller, *signatures.quantisation);
  }
  if (signatures.vibration) findings.push_back(*signatures.vibration);
  return findings;
}

}  // namespace flange::diagnose
