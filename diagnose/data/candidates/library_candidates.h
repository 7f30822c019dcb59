// SPDX-License-Identifier: MIT
// The library's candidates of a round: each class's formula fitted on the calibration part with
// the picks before it held, the best of them again with those picks refitted around them, and
// scored on the held-out part.
#pragma once

#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "candidate.h"
#include "parts.h"

namespace flange::diagnose {

// The library's candidates of the rounds weighed so far, for the other pass: the free-shape pass's
// first round weighs the same library candidates, on the same targets, as the library pass's first
// round did, and so do its later rounds while it picks as the library pass did. They are fitted
// once (their fits are a third of a 100 Hz diagnosis). A round is found again only when everything
// its fits depend on is the same.
class LibraryRounds {
 public:
  struct Key {
    std::vector<std::string> names;  // the candidates' effects
    std::vector<sim::EffectSettings> modelled;
    std::size_t first_selected = 0;
    std::vector<double> cal_v, ho_v;  // the calibration and held-out targets
    double noise_v = 0.0;             // the round's noise level (which candidates are refitted)
    bool operator==(const Key&) const = default;
  };

  std::optional<std::vector<Candidate>> find(const Key& key) const {
    const std::lock_guard<std::mutex> lock(mutex_);
    for (const auto& [k, candidates] : rounds_) {
      if (k == key) return candidates;
    }
    return std::nullopt;
  }
  void keep(Key key, const std::vector<Candidate>& candidates) {
    const std::lock_guard<std::mutex> lock(mutex_);
    rounds_.emplace_back(std::move(key), candidates);
  }

 private:
  mutable std::mutex mutex_;
  std::vector<std::pair<Key, std::vector<Candidate>>> rounds_;
};

// One round of the greedy selection that picked an effect: every candidate it weighed (their

// Refits every selected effect (from `first` on) once, with the others held. A greedy pick is
// fitted before the effects found after it, so it soaks up part of them (an offset drift takes
// some of an ageing offset); the refit hands that part back. A refit is kept only where it
// lowers the calibration RMS, since fit_effect searches afresh rather than from the last fit.
void backfit(std::vector<sim::EffectSettings>& modelled, std::size_t first,
             const TwinReplay& replay, const std::vector<double>& real_v);

// The library's candidates of a round (`round`: their names, the effects modelled and the
// targets), in the order of round.names, each fitted on the calibration part with the picks before
// it held and scored on the held-out part; those candidates_to_refit names are then fitted again
// with the picks before them refitted around them (backfit) and scored again. Found in `rounds`
// when the other pass weighed the same round; else fitted (each in its own thread: the replays are
// read-only; the classes that took longest last time start first, longest_first.h; the results
// are taken in order, so the outcome does not depend on the threads) and kept there.
std::vector<Candidate> library_candidates(const Parts& parts, LibraryRounds& rounds,
                                          LibraryRounds::Key round);

// Which of a round's candidates, screened with the picks before them held, are refitted: the
// criteria::kRefittedCandidatesOfARound with the least held-out mean square (`heldout_ms`), every
// other within criteria::kRefitAlsoWithin of noise_v^2 of that least, and the
// criteria::kRefittedCandidatesOfARound that fit the calibration part best (`calibration_ms`),
// the first of equals each time; in ascending order, each once.
std::vector<std::size_t> candidates_to_refit(const std::vector<double>& heldout_ms,
                                             const std::vector<double>& calibration_ms,
                                             double noise_v);

}  // namespace flange::diagnose
