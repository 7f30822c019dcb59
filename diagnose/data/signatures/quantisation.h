// SPDX-License-Identifier: MIT
// The converter, recognised when the voltages of both parts lie on one converter grid. The twin's
// converter on that grid is kept when it reproduces the recorded codes (what it leaves is within
// criteria::kExplainedRatio of what the noise alone would leave); when it does not (the thresholds
// sit elsewhere: a truncating converter, a gain or offset calibration in the DAQ software), the
// quantisation is taken as noise of LSB / sqrt(12), which the effective white noise already holds.
#pragma once

#include <optional>

#include "parts.h"
#include "selection.h"
#include "signatures.h"
#include "white_noise.h"

namespace flange::diagnose {

// The converter as recognised on the selection's final state.
struct QuantisationSignature {
  // The finding (with its own shrink: with the boundaries placed first, what placing them took
  // off the held-out gap; else what the converter's replay takes), the grid and whether it is
  // taken as noise: Signatures' quantisation, quantised_on and quantisation_as_noise.
  std::optional<EffectFinding> finding;
  std::optional<AdcGrid> grid;
  bool as_noise = false;
  // When the twin's converter reproduces the codes: it joins the model and replaces the
  // placement's offset (with_converter_replayed).
  std::optional<ConverterReplay> replay;
};

// A twin that holds the converter, or whose noise holds the rounding of this grid
// (`held_rounding_lsb_v`, sim::NoiseSettings::rounding_lsb_v, within criteria::kSameGridShare of
// its LSB), gives only the grid (and, for the latter, as_noise): the grid is no finding again.
QuantisationSignature recognise_quantisation(const Parts& parts, const WhiteNoise& white,
                                             double held_rounding_lsb_v,
                                             const Selection& selection);

}  // namespace flange::diagnose
