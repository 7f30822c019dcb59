// SPDX-License-Identifier: MIT
// Candidate effects for the diagnosis, fitted with the catalogue's own implementations: the
// deterministic ones by minimising the voltage-gap RMS over their parameters (Nelder-Mead from
// the best point of a coarse lattice, noise off), the noise-like ones recognised from their
// signature in the gap.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "effect_catalogue.h"
#include "twin_replay.h"

namespace flange::diagnose {

// Effects fitted by their bias (the class table's Identification::kByBias).
bool fitted_by_bias(const std::string& name);

struct EffectFit {
  sim::EffectSettings settings;  // every parameter; the fitted ones and fixed defaults
  double rms_v = 0.0;            // calibration voltage-gap RMS with it added
  int evaluations = 0;           // replays spent
};

// Fits `name` on top of `modelled` (effects already in the twin), minimising
// RMS(real_v - replay(modelled + name)) over the replay's search rows (every row up to
// TwinReplay::kSearchRows); rms_v is on every row.
EffectFit fit_effect(const std::string& name, const TwinReplay& replay,
                     const std::vector<double>& real_v,
                     const std::vector<sim::EffectSettings>& modelled);

// The classes' fitters (candidates/class_fits.h, ClassFit::fit). fit_by_search: a coarse lattice over the class's
// search ranges, then Nelder-Mead from its best point. fit_mains: the same with the mains
// standard (50 or 60 Hz) chosen among those whose fundamental does not alias to 0 Hz (infinite
// RMS when neither is left). fit_ageing: the ageing drift is linear in time, gap = r (a0 + t /
// day), solved by least squares of the gap on [1, t] within the catalogue's limits.
EffectFit fit_by_search(const std::string& name, const TwinReplay& replay,
                        const std::vector<double>& real_v,
                        const std::vector<sim::EffectSettings>& modelled);
EffectFit fit_mains(const std::string& name, const TwinReplay& replay,
                    const std::vector<double>& real_v,
                    const std::vector<sim::EffectSettings>& modelled);
EffectFit fit_ageing(const std::string& name, const TwinReplay& replay,
                     const std::vector<double>& real_v,
                     const std::vector<sim::EffectSettings>& modelled);

// Which parameters a fit varies (others stay at the catalogue's defaults).
std::vector<std::string> fitted_keys(const std::string& name);

}  // namespace flange::diagnose
