// SPDX-License-Identifier: MIT
#include "free_shape_candidates.h"

#include "longest_first.h"
#include "series_statistics.h"
#include "series_arithmetic.h"

namespace flange::diagnose {

Candidate free_shape_candidate(const FreeShapeFamily& family, const FreeShapeRound& round) {
  Candidate c;
  c.free_shape = fit_free_shape(family, {round.calibration, round.heldout, round.cal_gap_v,
                                         round.ho_gap_v, round.heldout_age_unknown,
                                         round.no_level_carried});
  c.fit.settings = sim::make_effect_settings(c.free_shape->family.effect, {}, "diagnose free shape");
  c.fit.rms_v = rms_of(minus(round.cal_gap_v, c.free_shape->cal_voltage_v));
  c.with = round.modelled;
  c.heldout_error = minus(round.ho_gap_v, c.free_shape->heldout_voltage_v);
  return c;
}

std::vector<Candidate> free_shape_candidates(const std::vector<FreeShapeFamily>& families,
                                             const FreeShapeRound& round) {
  std::vector<std::string> kinds;
  for (const FreeShapeFamily& family : families) {
    kinds.push_back("free shape " + family.effect + ", " + family.variable);
  }
  return parallel_map_longest_first<Candidate>(kinds, [&](std::size_t i) {
    return free_shape_candidate(families[i], round);
  });
}

}  // namespace flange::diagnose
