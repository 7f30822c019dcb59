// SPDX-License-Identifier: MIT
// How a round scores its candidates on held-out data, and the rules that choose among them:
// significance, tie, preference of the library's formula, and the first pick's chance gain
// (docs/diagnose.md, "Selection"; the criteria are in criteria.h).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "block_resamples.h"
#include "candidate.h"

namespace flange::diagnose {

// What a round's candidates are scored against: the held-out gap the picks so far leave, the
// held-out resamples, and the noise level of the round.
struct RoundScore {
  const std::vector<double>& current_error;
  const BlockResamples& resamples;
  double noise_v = 0.0;
};

// A candidate chosen in a round: its index, its held-out mean-square gain (V^2) and the gain's
// block-bootstrap criteria::kGainLowerQuantile quantile.
struct Choice {
  std::size_t best = 0;
  double gain = 0.0;
  double lower = 0.0;
};

// What fitting a candidate's held-out values (the mains' windows, a session's constant) would
// take from white noise alone: heldout_values / n of its variance, charged against every gain.
double chance_gain(const Candidate& c, double noise_v);

// The held-out mean square candidate `c` leaves, charged with its chance_gain.
double charged_mean_square(const Candidate& c, double noise_v);

// Of `candidates`, the one of class `name` with the least charged_mean_square, when that is below
// `below_ms`; none otherwise (a free family's refit may name another class).
std::optional<Candidate> best_of_class(std::vector<Candidate> candidates, const std::string& name,
                                       double noise_v, double below_ms);

// The held-out mean-square gain of candidate `c` over what the picks leave now.
double gain_of(const Candidate& c, const RoundScore& round);

// Candidate `index` as a choice: its gain and the gain's bootstrap lower quantile.
Choice choice_of(const std::vector<Candidate>& candidates, std::size_t index,
                 const RoundScore& round);

// The candidate that lowers the held-out mean square most (the first of equals). When free shapes
// compete, the fewest values win among those within criteria::kTieMargin of sigma^2 of the best:
// a family with more freedom must earn it on held-out data.
Choice best_candidate(const std::vector<Candidate>& candidates, const RoundScore& round,
                      bool free_shapes_compete);

// When the choice is a free shape whose class's library formula gains within
// criteria::kFreeShapeMustGainOverFormula of sigma^2 as much, the library's formula.
Choice prefer_library_formula(const std::vector<Candidate>& candidates, Choice choice,
                              const RoundScore& round);

// A gain is significant when it is at least `least_gain` (V^2) and its bootstrap lower bound is
// above zero.
bool significant(const Choice& choice, double least_gain);

// The round's choice: best_candidate, preferring the library's formula; when that choice is not
// significant against `least_gain`, the candidate of the largest gain that is (each again
// preferring its class's formula), or the unsignificant best when none is. A gain the held-out
// resamples do not confirm says the candidate's fit leans on a few stretches of the held-out
// session, not that nothing is there: a candidate that gains less on every stretch is the
// better-founded pick (criteria::kGainLowerQuantile). Only for a first pick, whose least gain is
// what the best candidate gains by chance (first_pick_least_gain).
Choice significant_choice(const std::vector<Candidate>& candidates, const RoundScore& round,
                          bool free_shapes_compete, double least_gain);

// The least gain a first pick must make, from the data at hand: each candidate's held-out
// prediction (what it takes off the gap) scored against the held-out gap circularly shifted by
// criteria::kChanceShifts lags spread over its middle 80 %. Shifted, the gap keeps its own level,
// spectrum and slow structure, but no longer lines up with what the candidates predict; the best
// candidate's gain at a lag is what the best of them gains by chance, and the largest over the
// lags is the least gain, kept between criteria::kLeastLeastGainOfAFirstPick and
// criteria::kMostLeastGainOfAFirstPick of sigma^2. A gap too short to shift keeps the larger.
double first_pick_least_gain(const std::vector<Candidate>& candidates, const RoundScore& round);

// Lags summed side by side in shifted_dots: each lag's sum is still one running sum in row order
// (the same bits as summed alone), but a core overlaps eight independent sums where one waits on
// each addition before the next (first_pick_least_gain's 64 lags over a 100 Hz part's rows).
inline constexpr std::size_t kShiftsAtOnce = 8;

// For each lag L: sum over the rows i, in row order, of gap[(i + L) mod n] * predicted[i] (the
// held-out gap circularly shifted by L against a prediction).
std::vector<double> shifted_dots(const std::vector<double>& gap,
                                 const std::vector<double>& predicted,
                                 const std::vector<std::size_t>& lags);

}  // namespace flange::diagnose
