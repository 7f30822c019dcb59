// SPDX-License-Identifier: MIT
// Where the selection starts: the twin as given, with the converter's code boundaries placed
// first when both parts lie on one grid, and whether a noise-type class shows before any pick.
#pragma once

#include <vector>

#include "effect_catalogue.h"
#include "parts.h"
#include "selection.h"

namespace flange::diagnose {

// `twin_effects`: the twin's own effects; `cal_base_v`, `ho_base_v`: the twin replayed on each
// part; `noise_v`: the estimated white noise.
Selection starting_selection(const Parts& parts,
                             const std::vector<sim::EffectSettings>& twin_effects,
                             const std::vector<double>& cal_base_v,
                             const std::vector<double>& ho_base_v, double noise_v);

}  // namespace flange::diagnose
