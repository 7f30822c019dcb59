// SPDX-License-Identifier: MIT
// The state the selection's steps hand on to each other once the nominal twin is replayed: the
// effects modelled, the picks (each one value: its finding, its round and where its effect sits in
// the model), what the free shapes and the converter's placement add to the twin's voltage, and
// the held-out gap that is left.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "adc_grid.h"
#include "block_resamples.h"
#include "candidate.h"
#include "converter_boundaries.h"
#include "diagnosis.h"
#include "parts.h"
#include "white_noise.h"

namespace flange::diagnose {

// One round of the greedy selection that picked an effect: every candidate it weighed (their
// held-out gaps are scored again on resamples for the inclusion), the one it picked, and the noise
// level it was scored against.
struct Step {
  std::vector<Candidate> candidates;
  std::size_t chosen = 0;
  double noise_v = 0.0;
};

// A bias-type pick.
struct Pick {
  EffectFinding finding;
  Step step;
  // Its library effect's index in Selection::modelled; -1: a free shape, which has none.
  int modelled_index = -1;
  const Candidate& chosen() const { return step.candidates[step.chosen]; }
};

struct Selection {
  std::vector<sim::EffectSettings> modelled;  // the twin's own effects, then the picks
  std::size_t first_selected = 0;             // where the picks start in `modelled`
  std::vector<double> ho_gap;                 // held-out gap the picks start from
  // The held-out gap of the twin as given: ho_gap unless the converter's boundaries were placed
  // first (their offset is then in ho_gap, not here). What "before" means in the report.
  std::vector<double> raw_ho_gap;
  std::vector<double> current_error;  // held-out gap `modelled` and the free shapes leave
  // The twin's white noise the next round is scored against, V (>= 1e-9): the estimate, lowered
  // when the picks leave a gap whose noise estimate is lower (each Step keeps its round's).
  double noise_v = 0.0;
  // The white noise re-estimated on what the picks leave, when that was lower than the noise
  // stage's: then noise_v is its level, and the diagnosis reports it as the twin's noise.
  std::optional<WhiteNoise> reestimated_noise;
  BlockResamples resamples;  // of the held-out part
  std::vector<Pick> picks;   // in selection order
  // The converter's code boundaries (and a DAQ gain), when placed before the picks; what they add
  // to the twin's voltage is in cal_free_v and ho_free_v.
  std::optional<ConverterPlacement> converter;
  // Mount motion shows in both parts' first gaps, or both parts lie on one converter grid: a
  // first pick then needs criteria::kLeastGainOfAPick, like the later ones.
  bool noise_type_before_picks = false;
  // The least held-out gain a first pick must make on this data (V^2): set in the first round
  // from the candidates' chance gains against the held-out gap shifted in time.
  double first_pick_least_gain = 0.0;
  std::optional<EffectFinding> nearest_unpicked;  // the best candidate when none was significant
  // What the free-shape picks and the converter's placement add to the twin's voltage, per part.
  std::vector<double> cal_free_v, ho_free_v;
  bool free_shapes = false;     // whether the free-shape families compete (the second pass)
  bool shapes_refined = false;  // whether a library pick was given a free shape after the rounds
  std::vector<std::string> confounded;  // one sentence per pick another class explained as well
  std::vector<std::string> dropped;     // one sentence per pick the backward steps took out
  // The noise-type classes, recognised from their signatures after the picks.
  std::optional<EffectFinding> quantisation;
  std::optional<AdcGrid> quantised_on;  // the converter grid, once recognised
  bool quantisation_as_noise = false;   // its codes not reproduced: taken as noise
  std::optional<EffectFinding> vibration;
};

// Every finding in the order the report lists them: the picks in the order the rounds took them,
// the converter before the first pick that takes less of the held-out gap's RMS than its rounding
// puts in it (LSB / sqrt(12)), mount motion last.
std::vector<EffectFinding> findings_of(const Selection& selection);

// The recorded voltage less what the free-shape picks add: what the replayed effects must meet.
std::vector<double> cal_target(const Parts& parts, const Selection& selection);
std::vector<double> ho_target(const Parts& parts, const Selection& selection);

// Whether `name`'s class is already modelled: by the library effect or by its free shape.
bool class_taken(const std::string& name, const Selection& selection);

// Adds `sign` times what a free shape adds to the twin's voltage to both parts' free voltages.
void add_free_shape(Selection& selection, const FreeShapeFit& shape, double sign);

// Takes the library effect at `index` out of `modelled`; the picks' indices into it follow.
void erase_library_effect(Selection& selection, int index);

// Each library pick's finding carries its effect's parameters as last refitted.
void refresh_library_params(Selection& selection);

}  // namespace flange::diagnose
