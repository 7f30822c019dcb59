// SPDX-License-Identifier: MIT
#include "start.h"

#include "converter_boundaries.h"
#include "series_arithmetic.h"
#include "vibration_signature.h"

namespace flange::diagnose {

Selection starting_selection(const Parts& parts,
                             const std::vector<sim::EffectSettings>& twin_effects,
                             const std::vector<double>& cal_base_v,
                             const std::vector<double>& ho_base_v, double noise_v) {
  Selection selection;
  selection.modelled = twin_effects;
  selection.noise_v = noise_v;
  selection.cal_free_v.assign(parts.calibration.size(), 0.0);
  selection.ho_free_v.assign(parts.heldout.size(), 0.0);
  selection.raw_ho_gap = minus(parts.heldout.voltage_v, ho_base_v);
  selection.converter = place_converter_boundaries(parts, selection.modelled, noise_v);
  if (selection.converter) {
    selection.cal_free_v = selection.converter->cal_added_v;
    selection.ho_free_v = selection.converter->ho_added_v;
  }
  selection.ho_gap = minus(ho_target(parts, selection), ho_base_v);
  // Mount motion in both parts' first gaps, or a converter grid: a noise-type class shows before
  // any pick, and a first pick then needs what the later ones need.
  const bool motion =
      vibration_signature(minus(cal_target(parts, selection), cal_base_v),
                          parts.cal_replay.sensitivity_v_per_mm(), parts.calibration.clearance_mm)
          .present &&
      vibration_signature(selection.ho_gap, parts.ho_replay.sensitivity_v_per_mm(),
                          parts.heldout.clearance_mm)
          .present;
  selection.noise_type_before_picks = motion || parts.grid.has_value();
  return selection;
}

}  // namespace flange::diagnose
