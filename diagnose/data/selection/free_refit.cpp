// SPDX-License-Identifier: MIT
#include "free_refit.h"

#include <optional>
#include <string>
#include <vector>

#include "coil_parts.h"
#include "effect_classes.h"
#include "family_makers.h"
#include "free_shape_candidates.h"
#include "library_candidates.h"
#include "scoring.h"
#include "series_arithmetic.h"
#include "series_statistics.h"

namespace flange::diagnose {
namespace {

// Whether none of the picks other than pick `j` carries a level between the sessions (forward.h's
// no_level_carried, without the pick refitted).
bool no_level_carried_without(const Selection& selection, std::size_t j) {
  for (std::size_t k = 0; k < selection.picks.size(); ++k) {
    if (k != j && !effect_class(selection.picks[k].finding.name).carries_no_level) return false;
  }
  return true;
}

// Pick `j`'s family fitted again on what the others leave; its curve replaced where the held-out
// mean square falls.
// `as`: the family to fit it by in place of its own (nullptr: its own).
void refit_free_pick(const Parts& parts, Selection& selection, std::size_t j,
                     const FreeShapeFamily* as = nullptr) {
  Pick& pick = selection.picks[j];
  if (pick.modelled_index >= 0 || !pick.chosen().free_shape) return;
  const FreeShapeFit old_shape = *pick.chosen().free_shape;
  const double now = rms_of(selection.current_error);
  const double now_ms = now * now + chance_gain(pick.chosen(), selection.noise_v);
  add_free_shape(selection, old_shape, -1.0);
  const std::vector<double> cal_gap =
      minus(cal_target(parts, selection), parts.cal_replay.voltage(selection.modelled));
  const std::vector<double> ho_gap =
      minus(ho_target(parts, selection), parts.ho_replay.voltage(selection.modelled));
  const CoilParts coil(parts, selection.modelled);
  const FreeShapeRound round{coil.calibration(),        coil.heldout(),
                             cal_gap,                   ho_gap,
                             selection.modelled,        parts.heldout_age_unknown,
                             no_level_carried_without(selection, j)};
  std::optional<Candidate> best =
      best_of_class(free_shape_candidates({as ? *as : old_shape.family}, round), pick.finding.name,
                    selection.noise_v, now_ms);
  if (!best) {
    add_free_shape(selection, old_shape, 1.0);
    return;
  }
  add_free_shape(selection, *best->free_shape, 1.0);
  backfit(selection.modelled, selection.first_selected, parts.cal_replay,
          cal_target(parts, selection));
  selection.current_error =
      minus(ho_target(parts, selection), parts.ho_replay.voltage(selection.modelled));
  pick.finding.params = best->free_shape->params;
  refresh_library_params(selection);
  pick.step.candidates[pick.step.chosen].free_shape = best->free_shape;
}

}  // namespace

void refit_earlier_free_picks(const Parts& parts, Selection& selection) {
  for (std::size_t j = 0; j + 1 < selection.picks.size(); ++j) refit_free_pick(parts, selection, j);
}

void refine_temperature_curves(const Parts& parts, Selection& selection) {
  for (std::size_t j = 0; j < selection.picks.size(); ++j) {
    const Pick& pick = selection.picks[j];
    if (pick.modelled_index >= 0 || !pick.chosen().free_shape) continue;
    FreeShapeFamily fine = pick.chosen().free_shape->family;
    if (fine.make == free_shapes::make_temperature_offset_curve) {
      fine.make = free_shapes::make_fine_temperature_offset_curve;
    } else if (fine.make == free_shapes::make_temperature_gain_curve) {
      fine.make = free_shapes::make_fine_temperature_gain_curve;
    } else {
      continue;
    }
    refit_free_pick(parts, selection, j, &fine);
  }
}

}  // namespace flange::diagnose
