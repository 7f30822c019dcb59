// SPDX-License-Identifier: MIT
#include "library_candidates.h"

#include "parallel_work.h"
#include "series_statistics.h"
#include "series_arithmetic.h"

namespace flange::diagnose {
namespace {

std::vector<Candidate> fit_library_candidates(const Parts& parts,
                                              const LibraryRounds::Key& round) {
  std::vector<Candidate> candidates =
      parallel_map<Candidate>(round.names.size(), [&](std::size_t i) {
        const std::string& name = round.names[i];
        Candidate c;
        c.fit = fit_effect(name, parts.cal_replay, round.cal_v, round.modelled);
        c.with = round.modelled;
        c.with.push_back(c.fit.settings);
        // Each candidate is scored with the effects chosen before it refitted around it.
        if (c.with.size() > round.first_selected + 1) {
          backfit(c.with, round.first_selected, parts.cal_replay, round.cal_v);
        }
        c.heldout_error = minus(round.ho_v, parts.ho_replay.voltage(c.with));
        return c;
      });
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

int free_values_of(const Candidate& c) {
  return c.free_shape ? c.free_shape->free_values
                      : static_cast<int>(fitted_keys(c.fit.settings.name).size());
}

}  // namespace flange::diagnose
