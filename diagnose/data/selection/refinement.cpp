// SPDX-License-Identifier: MIT
#include "refinement.h"

#include <optional>
#include <string>
#include <vector>

#include "coil_parts.h"
#include "criteria.h"
#include "effect_classes.h"
#include "evidence.h"
#include "free_shape_candidates.h"
#include "library_candidates.h"
#include "scoring.h"
#include "series_statistics.h"
#include "series_arithmetic.h"
#include "twin_replay.h"

namespace flange::diagnose {

void give_pick_a_free_shape(const Parts& parts, Selection& selection, std::size_t j) {
  const int index = selection.picks[j].modelled_index;
  if (index < 0) return;
  const std::string name = selection.modelled[static_cast<std::size_t>(index)].name;
  std::vector<sim::EffectSettings> others = selection.modelled;
  others.erase(others.begin() + index);
  const std::vector<double> cal_gap =
      minus(cal_target(parts, selection), parts.cal_replay.voltage(others));
  const std::vector<double> ho_gap =
      minus(ho_target(parts, selection), parts.ho_replay.voltage(others));
  const CoilParts coil(parts, others);
  const double variance = selection.noise_v * selection.noise_v;
  const double now = rms_of(selection.current_error);
  std::vector<FreeShapeFamily> families;
  for (const FreeShapeFamily& family : free_shape_families()) {
    if (family.effect != name) continue;
    if (parts.grid && !family.weighed_on_a_converter_grid) continue;
    families.push_back(family);
  }
  const FreeShapeRound round{coil.calibration(), coil.heldout(), cal_gap,
                             ho_gap,             others,         parts.heldout_age_unknown,
                             selection.picks.size() == 1};
  std::optional<Candidate> best =
      best_of_class(free_shape_candidates(families, round), name, selection.noise_v,
                    now * now - criteria::kRefinementAcceptance * variance);
  if (!best) return;
  const FreeShapeFit& shape = *best->free_shape;
  erase_library_effect(selection, index);
  Pick& pick = selection.picks[j];
  pick.modelled_index = -1;
  add_free_shape(selection, shape, 1.0);
  backfit(selection.modelled, selection.first_selected, parts.cal_replay,
          cal_target(parts, selection));
  selection.current_error =
      minus(ho_target(parts, selection), parts.ho_replay.voltage(selection.modelled));
  pick.finding.params = shape.params;
  pick.finding.evidence +=
      evidence::given_a_free_shape(now, rms_of(selection.current_error), shape.description);
  refresh_library_params(selection);
  // Its round now chooses the free shape (the later rounds' scores were made beside the library's
  // formula: measure_inclusion reads the final fit instead for such a selection).
  pick.step.candidates.push_back(std::move(*best));
  pick.step.chosen = pick.step.candidates.size() - 1;
  selection.shapes_refined = true;
}

namespace {

// Whether pick j is a library effect that makes a channel late (a lag of the reading, a skew):
// the other classes' free shapes follow the inputs it leaves the coil (CoilParts).
bool delays_a_channel(const Selection& selection, std::size_t j) {
  const int index = selection.picks[j].modelled_index;
  if (index < 0) return false;
  const sim::EffectSettings& effect = selection.modelled[static_cast<std::size_t>(index)];
  return delays_temperature_channel(effect) || channel_delay_of(effect).voltage_late();
}

}  // namespace

Selection with_free_shapes_of_its_classes(const Parts& parts, const Selection& library) {
  Selection refined = library;
  // Picks that delay a channel first: a free shape fitted behind a library delay that a free shape
  // then replaced would follow inputs no effect of the final selection makes.
  std::vector<std::size_t> order;
  for (const bool delays : {true, false}) {
    for (std::size_t j = 0; j < refined.picks.size(); ++j) {
      if (delays_a_channel(refined, j) == delays) order.push_back(j);
    }
  }
  for (const std::size_t j : order) give_pick_a_free_shape(parts, refined, j);
  return refined;
}

}  // namespace flange::diagnose
