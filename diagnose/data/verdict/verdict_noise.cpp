// SPDX-License-Identifier: MIT
#include "verdict_noise.h"

#include "quantised_noise.h"
#include "verdict_reasons.h"

namespace flange::diagnose {

VerdictNoise with_converter_grid(const Signatures& signatures, const WhiteNoise& white,
                                 VerdictNoise noise) {
  if (!signatures.quantised_on) return noise;
  if (signatures.quantisation_as_noise) {
    const std::string why = reasons::quantisation_as_noise(white.effective_std_v);
    return {noise.rms_v, noise.why.empty() ? why : noise.why + "; " + why};
  }
  const double null_rms = quantised_null_rms(white.analog_std_v, signatures.quantised_on->lsb_v);
  const std::string why =
      reasons::converter_grid_modelled(null_rms, white.analog_std_v, signatures.quantised_on->lsb_v);
  if (noise.why.empty()) return {null_rms, why};
  return null_rms > noise.rms_v ? VerdictNoise{null_rms, noise.why + "; " + why} : noise;
}

}  // namespace flange::diagnose
