// SPDX-License-Identifier: MIT
#include "library_candidates.h"

#include <algorithm>
#include <cmath>

#include "criteria.h"
#include "longest_first.h"
#include "series_statistics.h"
#include "series_arithmetic.h"

namespace flange::diagnose {
namespace {

// Every candidate fitted with the picks before it held, and scored on the held-out part.
std::vector<Candidate> screen_library_candidates(const Parts& parts,
                                                 const LibraryRounds::Key& round) {
  std::vector<std::string> kinds;
  for (const std::string& name : round.names) kinds.push_back("library screen " + name);
  return parallel_map_longest_first<Candidate>(kinds, [&](std::size_t i) {
    Candidate c;
    c.fit = fit_effect(round.names[i], parts.cal_replay, round.cal_v, round.modelled);
    c.with = round.modelled;
    c.with.push_back(c.fit.settings);
    c.heldout_error = minus(round.ho_v, parts.ho_replay.voltage(c.with));
    return c;
  });
}

std::vector<Candidate> fit_library_candidates(const Parts& parts,
                                              const LibraryRounds::Key& round) {
  std::vector<Candidate> candidates = screen_library_candidates(parts, round);
  if (round.modelled.size() <= round.first_selected) return candidates;  // no picks to refit
  // The best of the screen scored with the picks before them refitted around them.
  std::vector<double> screened_ms, calibration_ms;
  for (const Candidate& c : candidates) {
    screened_ms.push_back(std::pow(rms_of(c.heldout_error), 2));
    calibration_ms.push_back(c.fit.rms_v * c.fit.rms_v);
  }
  const std::vector<std::size_t> refitted =
      candidates_to_refit(screened_ms, calibration_ms, round.noise_v);
  // A class's refit not yet timed is claimed as long as its screen took: the classes slow to
  // screen (a coil or a channel effect replayed at every step) are slow to refit around.
  std::vector<std::string> kinds, like;
  for (const std::size_t i : refitted) {
    kinds.push_back("library refit " + round.names[i]);
    like.push_back("library screen " + round.names[i]);
  }
  std::vector<Candidate> refits = parallel_map_longest_first<Candidate>(kinds, [&](std::size_t k) {
    Candidate c = candidates[refitted[k]];
    backfit(c.with, round.first_selected, parts.cal_replay, round.cal_v);
    c.heldout_error = minus(round.ho_v, parts.ho_replay.voltage(c.with));
    return c;
  }, like);
  for (std::size_t k = 0; k < refitted.size(); ++k) {
    candidates[refitted[k]] = std::move(refits[k]);
  }
  return candidates;
}

}  // namespace

void backfit(std::vector<sim::EffectSettings>& modelled, std::size_t first,
             const TwinReplay& replay, const std::vector<double>& real_v) {
  double rms_now = rms_of(minus(real_v, replay.voltage(modelled)));
  for (std::size_t j = first; j < modelled.size(); ++j) {
    std::vector<sim::EffectSettings> others = modelled;
    others.erase(others.begin() + static_cast<long>(j));
    const EffectFit refit = fit_effect(modelled[j].name, replay, real_v, others);
    if (refit.rms_v < rms_now) {
      modelled[j] = refit.settings;
      rms_now = refit.rms_v;
    }
  }
}


std::vector<Candidate> library_candidates(const Parts& parts, LibraryRounds& rounds,
                                          LibraryRounds::Key round) {
  if (auto weighed = rounds.find(round)) return std::move(*weighed);
  std::vector<Candidate> candidates = fit_library_candidates(parts, round);
  rounds.keep(std::move(round), candidates);
  return candidates;
}

std::vector<std::size_t> candidates_to_refit(const std::vector<double>& heldout_ms,
                                             const std::vector<double>& calibration_ms,
                                             double noise_v) {
  const auto ascending = [](const std::vector<double>& ms) {
    std::vector<std::size_t> order(ms.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return ms[a] < ms[b]; });
    return order;
  };
  const std::vector<std::size_t> by_heldout = ascending(heldout_ms);
  const std::vector<std::size_t> by_calibration = ascending(calibration_ms);
  const double alike = criteria::kRefitAlsoWithin * noise_v * noise_v;
  const auto best = static_cast<std::size_t>(criteria::kRefittedCandidatesOfARound);
  std::vector<std::size_t> refitted;
  for (std::size_t k = 0; k < by_heldout.size(); ++k) {
    const std::size_t i = by_heldout[k];
    if (k < best || heldout_ms[i] <= heldout_ms[by_heldout[0]] + alike) refitted.push_back(i);
  }
  for (std::size_t k = 0; k < std::min(best, by_calibration.size()); ++k) {
    refitted.push_back(by_calibration[k]);
  }
  std::sort(refitted.begin(), refitted.end());
  refitted.erase(std::unique(refitted.begin(), refitted.end()), refitted.end());
  return refitted;
}

int free_values_of(const Candidate& c) {
  return c.free_shape ? c.free_shape->free_values
                      : static_cast<int>(fitted_keys(c.fit.settings.name).size());
}

}  // namespace flange::diagnose
