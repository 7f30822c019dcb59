// SPDX-License-Identifier: MIT
#include "forward.h"

#include <algorithm>
#include <optional>

#include "coil_parts.h"
#include "criteria.h"
#include "effect_classes.h"
#include "evidence.h"
#include "free_refit.h"
#include "free_shape_candidates.h"
#include "library_candidates.h"
#include "series_statistics.h"
#include "series_arithmetic.h"
#include "white_noise.h"

namespace flange::diagnose {
namespace {

// For a free-shape choice: how far the library's own formula of the class went in the same
// round, so the report says how the shape departs from it.
void compare_with_library(const std::vector<Candidate>& candidates, const Choice& choice,
                          const RoundScore& round, EffectFinding& finding) {
  const Candidate& chosen = candidates[choice.best];
  if (!chosen.free_shape) return;
  for (const Candidate& c : candidates) {
    if (c.free_shape || c.fit.settings.name != chosen.fit.settings.name) continue;
    finding.evidence +=
        evidence::library_formula_beside(c.fit.settings.params, gain_of(c, round), choice.gain);
  }
}

// When a candidate of another class gains within criteria::kConfoundingMargin of sigma^2 of the
// choice's, the two are confounded on this protocol: the pick stands, and a sentence says so and
// which data would separate them.
void note_confounding(const std::vector<Candidate>& candidates, const Choice& choice,
                      const std::vector<std::string>& alike, Selection& selection) {
  const Candidate& chosen = candidates[choice.best];
  for (const std::string& other : alike) {
    selection.confounded.push_back(evidence::confounded(
        effect_class(chosen.fit.settings.name), effect_class(other), criteria::kConfoundingMargin));
  }
}

// A deterministic effect in the gap (a mains tone, a lag on the clearance steps) inflates the
// difference-based noise estimate; estimate it again from what the picks leave, kept if lower.
void reestimate_noise(const Parts& parts, const std::optional<AdcGrid>& cal_grid,
                      Selection& selection) {
  WhiteNoise left = estimate_white_noise(
      cal_target(parts, selection), parts.cal_replay.voltage(selection.modelled), cal_grid);
  if (left.effective_std_v < selection.noise_v) {
    left.source = "re-estimated on the calibration gap the selected effects leave: " + left.source;
    selection.noise_v = std::max(left.effective_std_v, 1e-9);
    selection.reestimated_noise = std::move(left);
  }
}

}  // namespace

bool no_level_carried(const Selection& selection) {
  return std::all_of(selection.picks.begin(), selection.picks.end(), [](const Pick& pick) {
    return effect_class(pick.finding.name).carries_no_level;
  });
}

std::vector<std::string> confounded_classes(const std::vector<Candidate>& candidates,
                                            const Choice& choice, const RoundScore& round) {
  const Candidate& chosen = candidates[choice.best];
  const double margin = criteria::kConfoundingMargin * round.noise_v * round.noise_v;
  std::vector<std::string> alike;
  for (const Candidate& c : candidates) {
    const std::string& name = c.fit.settings.name;
    if (name == chosen.fit.settings.name ||
        std::find(alike.begin(), alike.end(), name) != alike.end()) {
      continue;
    }
    if (gain_of(c, round) >= choice.gain - margin) alike.push_back(name);
  }
  return alike;
}

RoundScore round_score(const Selection& selection) {
  return {selection.current_error, selection.resamples, selection.noise_v};
}

RoundScore tie_score(const Selection& selection) {
  const double floor = criteria::kTieFloorShareOfGap * rms_of(selection.current_error);
  return {selection.current_error, selection.resamples, std::max(selection.noise_v, floor)};
}

double least_gain_of_next_pick(const Selection& selection) {
  return selection.picks.empty() && !selection.noise_type_before_picks
             ? selection.first_pick_least_gain
             : criteria::kLeastGainOfAPick * selection.noise_v * selection.noise_v;
}

std::vector<Candidate> round_candidates(const Parts& parts, LibraryRounds& rounds,
                                        const Selection& selection) {
  const std::vector<sim::EffectSettings>& modelled = selection.modelled;
  const std::vector<double> cal_v = cal_target(parts, selection);
  std::vector<std::string> names;
  for (const std::string& name : bias_classes_in_catalogue_order()) {
    if (!class_taken(name, selection)) names.push_back(name);
  }
  std::vector<Candidate> candidates = library_candidates(
      parts, rounds,
      {names, modelled, selection.first_selected, cal_v, ho_target(parts, selection),
       selection.noise_v});
  if (!selection.free_shapes) return candidates;
  const std::vector<double> cal_gap = minus(cal_v, parts.cal_replay.voltage(modelled));
  std::vector<FreeShapeFamily> families;
  for (const FreeShapeFamily& family : free_shape_families()) {
    if (class_taken(family.effect, selection)) continue;
    if (parts.grid && !family.weighed_on_a_converter_grid) continue;
    families.push_back(family);
  }
  const CoilParts coil(parts, modelled);
  const FreeShapeRound round{coil.calibration(),         coil.heldout(), cal_gap,
                             selection.current_error,    modelled,       parts.heldout_age_unknown,
                             no_level_carried(selection)};
  for (Candidate& c : free_shape_candidates(families, round)) candidates.push_back(std::move(c));
  return candidates;
}

EffectFinding finding_for_choice(const Candidate& chosen, const Choice& choice,
                                 const std::vector<double>& current_error) {
  EffectFinding finding;
  finding.name = chosen.fit.settings.name;
  finding.params = chosen.free_shape ? chosen.free_shape->params : chosen.fit.settings.params;
  finding.heldout_rms_before = rms_of(current_error);
  finding.heldout_rms_after = rms_of(chosen.heldout_error);
  finding.shrink_pct =
      100.0 * (finding.heldout_rms_before - finding.heldout_rms_after) / finding.heldout_rms_before;
  finding.evidence = evidence::fitted_and_scored(chosen.fit.rms_v, choice.gain, choice.lower);
  if (const EffectClass& of = effect_class(finding.name); of.reported_as_noise) {
    finding.noise_type = true;
    finding.evidence += "; " + of.pick_note;
  }
  if (chosen.free_shape) {
    finding.evidence += "; not the library's formula: " + chosen.free_shape->description;
  }
  return finding;
}

void take_pick(std::vector<Candidate> candidates, const Choice& choice, Selection& selection) {
  const Candidate& chosen = candidates[choice.best];
  EffectFinding finding = finding_for_choice(chosen, choice, selection.current_error);
  compare_with_library(candidates, choice, round_score(selection), finding);
  selection.modelled = chosen.with;
  selection.current_error = chosen.heldout_error;
  Pick pick;
  pick.finding = std::move(finding);
  if (chosen.free_shape) {
    add_free_shape(selection, *chosen.free_shape, 1.0);
    pick.modelled_index = -1;
  } else {
    pick.modelled_index = static_cast<int>(selection.modelled.size()) - 1;
  }
  pick.step = {std::move(candidates), choice.best, selection.noise_v};
  selection.picks.push_back(std::move(pick));
  refresh_library_params(selection);
}

void select_bias_effects(const Parts& parts, LibraryRounds& rounds, const DiagnoseOptions& options,
                         const std::optional<AdcGrid>& cal_grid, Selection& selection) {
  selection.current_error = selection.ho_gap;
  selection.resamples =
      BlockResamples(parts.heldout.size(), options.bootstrap_rounds, options.seed);
  selection.first_selected = selection.modelled.size();
  for (int round = 0; round < criteria::kMostPicks; ++round) {
    std::vector<Candidate> candidates = round_candidates(parts, rounds, selection);
    if (candidates.empty()) break;
    const RoundScore score = round_score(selection);
    if (selection.picks.empty() && !selection.noise_type_before_picks) {  // else unused
      selection.first_pick_least_gain = first_pick_least_gain(candidates, score);
    }
    const double least_gain = least_gain_of_next_pick(selection);
    // The first pick's least gain is what the best of all candidates gains by chance, so any
    // candidate above it may be taken; a later round's is a flat floor, which the best of many
    // small confirmed gains would pass by chance: it keeps the best candidate or none.
    const Choice choice =
        selection.picks.empty()
            ? significant_choice(candidates, score, selection.free_shapes, least_gain)
            : prefer_library_formula(
                  candidates, best_candidate(candidates, score, selection.free_shapes), score);
    if (!significant(choice, least_gain)) {
      // Nothing significant at all: what came nearest is kept for an "unexplained" verdict.
      if (selection.picks.empty()) {
        selection.nearest_unpicked =
            finding_for_choice(candidates[choice.best], choice, selection.current_error);
      }
      break;
    }
    std::vector<std::string> alike = confounded_classes(candidates, choice, tie_score(selection));
    note_confounding(candidates, choice, alike, selection);
    take_pick(std::move(candidates), choice, selection);
    selection.picks.back().finding.indistinguishable_from = std::move(alike);
    if (selection.free_shapes) refit_earlier_free_picks(parts, selection);
    if (options.estimate_noise) reestimate_noise(parts, cal_grid, selection);
  }
}

}  // namespace flange::diagnose
