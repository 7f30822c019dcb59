// SPDX-License-Identifier: MIT
#include "final_fit.h"

#include <algorithm>

#include "series_statistics.h"
#include "series_arithmetic.h"

namespace flange::diagnose {

std::vector<double> heldout_error_with(const Parts& parts, const Selection& selection,
                                       const std::vector<bool>& kept) {
  std::vector<double> target = ho_target(parts, selection);
  std::vector<bool> in_library(selection.modelled.size(), true);
  for (std::size_t j = 0; j < kept.size(); ++j) {
    if (kept[j]) continue;
    const Pick& pick = selection.picks[j];
    if (pick.modelled_index >= 0) {
      in_library[static_cast<std::size_t>(pick.modelled_index)] = false;
      continue;
    }
    // A free shape: what it added comes back into the target.
    const std::vector<double>& added = pick.chosen().free_shape->heldout_voltage_v;
    for (std::size_t i = 0; i < target.size(); ++i) target[i] += added[i];
  }
  std::vector<sim::EffectSettings> library;
  for (std::size_t m = 0; m < selection.modelled.size(); ++m) {
    if (in_library[m]) library.push_back(selection.modelled[m]);
  }
  return minus(target, parts.ho_replay.voltage(library));
}

double heldout_rms_without(const Parts& parts, const Selection& selection, std::size_t j) {
  std::vector<bool> kept(selection.picks.size(), true);
  kept[j] = false;
  return rms_of(heldout_error_with(parts, selection, kept));
}

void measure_picks_in_final_fit(const Parts& parts, Selection& selection) {
  const std::size_t picks = selection.picks.size();
  std::vector<bool> kept(picks, false);
  double before = rms_of(selection.ho_gap);
  for (std::size_t k = 0; k < picks; ++k) {
    EffectFinding& f = selection.picks[k].finding;
    f.heldout_rms_without = heldout_rms_without(parts, selection, k);
    kept[k] = true;
    f.heldout_rms_before = before;
    f.heldout_rms_after = rms_of(heldout_error_with(parts, selection, kept));
    f.shrink_pct = 100.0 * (f.heldout_rms_before - f.heldout_rms_after) /
                   std::max(f.heldout_rms_before, 1e-30);
    before = f.heldout_rms_after;
  }
}

}  // namespace flange::diagnose
