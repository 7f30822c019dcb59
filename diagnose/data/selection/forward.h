// SPDX-License-Identifier: MIT
// The forward steps: greedy rounds of bias-type picks, each scored on held-out data.
#pragma once

#include <string>
#include <vector>

#include "candidate.h"
#include "library_candidates.h"
#include "parts.h"
#include "scoring.h"
#include "selection.h"

namespace flange::diagnose {

// The round's candidates: every bias class of the catalogue not yet modelled, its library formula
// fitted on top of `modelled` (library_candidates), in catalogue order; then, in the free-shape
// pass, the free shapes of the classes not yet modelled (the families the class table lists,
// in its order, where they are weighed on these parts).
std::vector<Candidate> round_candidates(const Parts& parts, LibraryRounds& rounds,
                                        const Selection& selection);

// The classes other than the choice's whose candidates gain within criteria::kConfoundingMargin
// of sigma^2 of the choice's gain, each once, in candidate order (what note_confounding names).
// Public for its test (tests/diagnose/selection_rules_test.cpp).
std::vector<std::string> confounded_classes(const std::vector<Candidate>& candidates,
                                            const Choice& choice, const RoundScore& round);

// Whether no pick so far can carry a level from the calibration session to the held-out one
// (none, or only classes with EffectClass::carries_no_level): a level between the sessions may
// then be chosen on the held-out part (FreeShapeInputs::no_level_carried). Public for its test
// (tests/diagnose/selection_rules_test.cpp).
bool no_level_carried(const Selection& selection);

// What a round is scored against.
RoundScore round_score(const Selection& selection);

// What ties are judged against: the round's score with its noise at least
// criteria::kTieFloorShareOfGap of the held-out gap's RMS the round starts from.
RoundScore tie_score(const Selection& selection);

// The least gain the next pick must make: first_pick_least_gain for a first pick where no
// noise-type class shows before any pick, else criteria::kLeastGainOfAPick of sigma^2.
double least_gain_of_next_pick(const Selection& selection);

// The finding for a chosen candidate: its fit and how far it shrinks the held-out gap.
EffectFinding finding_for_choice(const Candidate& chosen, const Choice& choice,
                                 const std::vector<double>& current_error);

// Adds the choice to the model as a pick; the earlier picks carry their parameters as refitted
// with it.
void take_pick(std::vector<Candidate> candidates, const Choice& choice, Selection& selection);

// Greedy selection of bias-type effects: at most criteria::kMostPicks, stopping at the first round
// whose best candidate is not significant; with options.estimate_noise, the noise is estimated
// again after each pick from what the picks leave (kept if lower: a deterministic effect in the
// gap, a mains tone or a lag on the steps, inflates the difference-based estimate), on the
// calibration part's converter grid `cal_grid`. The library rounds are found in, or kept in,
// `rounds` (library_candidates).
void select_bias_effects(const Parts& parts, LibraryRounds& rounds, const DiagnoseOptions& options,
                         const std::optional<AdcGrid>& cal_grid, Selection& selection);

}  // namespace flange::diagnose
