// SPDX-License-Identifier: MIT
#include "scoring.h"

#include <algorithm>
#include <cstddef>
#include <cmath>
#include <limits>
#include <utility>

#include "criteria.h"
#include "parallel_work.h"
#include "series_statistics.h"
#include "series_arithmetic.h"

namespace flange::diagnose {

double chance_gain(const Candidate& c, double noise_v) {
  if (!c.free_shape || c.free_shape->heldout_values == 0) return 0.0;
  return noise_v * noise_v * c.free_shape->heldout_values /
         static_cast<double>(std::max<std::size_t>(c.heldout_error.size(), 1));
}

double charged_mean_square(const Candidate& c, double noise_v) {
  const double after = rms_of(c.heldout_error);
  return after * after + chance_gain(c, noise_v);
}

std::optional<Candidate> best_of_class(std::vector<Candidate> candidates, const std::string& name,
                                       double noise_v, double below_ms) {
  std::optional<Candidate> best;
  double best_ms = below_ms;
  for (Candidate& c : candidates) {
    if (c.fit.settings.name != name) continue;
    const double ms = charged_mean_square(c, noise_v);
    if (ms < best_ms) {
      best_ms = ms;
      best = std::move(c);
    }
  }
  return best;
}

double gain_of(const Candidate& c, const RoundScore& round) {
  const double now = rms_of(round.current_error), after = rms_of(c.heldout_error);
  return now * now - after * after - chance_gain(c, round.noise_v);
}

Choice choice_of(const std::vector<Candidate>& candidates, std::size_t index,
                 const RoundScore& round) {
  Choice choice;
  choice.best = index;
  choice.gain = gain_of(candidates[index], round);
  const std::vector<double> now = round.resamples.mean_squares(round.current_error);
  const std::vector<double> after = round.resamples.mean_squares(candidates[index].heldout_error);
  std::vector<double> gains;
  for (std::size_t r = 0; r < now.size(); ++r) {
    gains.push_back(now[r] - after[r] - chance_gain(candidates[index], round.noise_v));
  }
  choice.lower = quantile(gains, criteria::kGainLowerQuantile);
  return choice;
}

Choice best_candidate(const std::vector<Candidate>& candidates, const RoundScore& round,
                      bool free_shapes_compete) {
  std::size_t best = 0;
  double best_gain = -std::numeric_limits<double>::infinity();
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    if (gain_of(candidates[c], round) > best_gain) {
      best_gain = gain_of(candidates[c], round);
      best = c;
    }
  }
  if (free_shapes_compete) {
    const double margin = criteria::kTieMargin * round.noise_v * round.noise_v;
    for (std::size_t c = 0; c < candidates.size(); ++c) {
      if (gain_of(candidates[c], round) >= best_gain - margin &&
          free_values_of(candidates[c]) < free_values_of(candidates[best])) {
        best = c;
      }
    }
  }
  return choice_of(candidates, best, round);
}

Choice prefer_library_formula(const std::vector<Candidate>& candidates, Choice choice,
                              const RoundScore& round) {
  const Candidate& best = candidates[choice.best];
  if (!best.free_shape) return choice;
  const double margin = criteria::kFreeShapeMustGainOverFormula * round.noise_v * round.noise_v;
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    if (candidates[c].free_shape || candidates[c].fit.settings.name != best.fit.settings.name) {
      continue;
    }
    if (choice.gain - gain_of(candidates[c], round) < margin) {
      return choice_of(candidates, c, round);
    }
  }
  return choice;
}

bool significant(const Choice& choice, double least_gain) {
  return choice.gain >= least_gain && choice.lower > 0.0;
}

Choice significant_choice(const std::vector<Candidate>& candidates, const RoundScore& round,
                          bool free_shapes_compete, double least_gain) {
  const Choice best = prefer_library_formula(
      candidates, best_candidate(candidates, round, free_shapes_compete), round);
  if (significant(best, least_gain)) return best;
  std::vector<std::size_t> by_gain(candidates.size());
  for (std::size_t c = 0; c < by_gain.size(); ++c) by_gain[c] = c;
  std::stable_sort(by_gain.begin(), by_gain.end(), [&](std::size_t a, std::size_t b) {
    return gain_of(candidates[a], round) > gain_of(candidates[b], round);
  });
  for (const std::size_t c : by_gain) {
    if (gain_of(candidates[c], round) < least_gain) break;
    const Choice choice = prefer_library_formula(candidates, choice_of(candidates, c, round), round);
    if (significant(choice, least_gain)) return choice;
  }
  return best;
}

double first_pick_least_gain(const std::vector<Candidate>& candidates, const RoundScore& round) {
  constexpr std::size_t kShifts = criteria::kChanceShifts;
  const double variance = round.noise_v * round.noise_v;
  const std::vector<double>& gap = round.current_error;
  const std::size_t n = gap.size();
  if (n < 10 * kShifts) return criteria::kMostLeastGainOfAFirstPick * variance;
  // Each candidate's gain at every lag on a core of its own, then the best at each lag taken in
  // candidate order (a maximum, whatever order the cores finish in).
  const auto gains_at_lags = [&](std::size_t candidate) {
    const Candidate& c = candidates[candidate];
    std::vector<double> predicted(n);  // what the candidate takes from the gap
    for (std::size_t i = 0; i < n; ++i) predicted[i] = gap[i] - c.heldout_error[i];
    double own = 0.0;  // the prediction's own sum of squares, the same at every lag
    for (std::size_t i = 0; i < n; ++i) own += std::pow(predicted[i], 2);
    std::vector<std::size_t> lags(kShifts);
    for (std::size_t k = 0; k < kShifts; ++k) {
      lags[k] = n / 10 + k * (8 * n / 10) / (kShifts - 1);
    }
    const std::vector<double> dots = shifted_dots(gap, predicted, lags);
    std::vector<double> gains(kShifts);
    for (std::size_t k = 0; k < kShifts; ++k) {
      gains[k] = (2.0 * dots[k] - own) / static_cast<double>(n) - chance_gain(c, round.noise_v);
    }
    return gains;
  };
  const std::vector<std::vector<double>> gains =
      parallel_map<std::vector<double>>(candidates.size(), gains_at_lags);
  std::vector<double> best_at_lag(kShifts, -std::numeric_limits<double>::infinity());
  for (const std::vector<double>& of_candidate : gains) {
    for (std::size_t k = 0; k < kShifts; ++k) {
      best_at_lag[k] = std::max(best_at_lag[k], of_candidate[k]);
    }
  }
  const double chance = *std::max_element(best_at_lag.begin(), best_at_lag.end());
  return std::clamp(chance, criteria::kLeastLeastGainOfAFirstPick * variance,
                    criteria::kMostLeastGainOfAFirstPick * variance);
}

std::vector<double> shifted_dots(const std::vector<double>& gap,
                                 const std::vector<double>& predicted,
                                 const std::vector<std::size_t>& lags) {
  const std::size_t n = gap.size();
  std::vector<double> dots(lags.size(), 0.0);
  if (n == 0) return dots;
  // The gap twice over: row i + L of it is row (i + L) mod n of the gap, for L < n.
  std::vector<double> twice(2 * n);
  std::copy(gap.begin(), gap.end(), twice.begin());
  std::copy(gap.begin(), gap.end(), twice.begin() + static_cast<std::ptrdiff_t>(n));
  const auto shifted = [&](std::size_t k) { return twice.data() + lags[k] % n; };
  std::size_t k = 0;
  static_assert(kShiftsAtOnce == 8, "the block below sums eight lags");
  for (; k + kShiftsAtOnce <= lags.size(); k += kShiftsAtOnce) {
    const double *g0 = shifted(k), *g1 = shifted(k + 1), *g2 = shifted(k + 2),
                 *g3 = shifted(k + 3), *g4 = shifted(k + 4), *g5 = shifted(k + 5),
                 *g6 = shifted(k + 6), *g7 = shifted(k + 7);
    double d0 = 0.0, d1 = 0.0, d2 = 0.0, d3 = 0.0, d4 = 0.0, d5 = 0.0, d6 = 0.0, d7 = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const double p = predicted[i];
      d0 += g0[i] * p;
      d1 += g1[i] * p;
      d2 += g2[i] * p;
      d3 += g3[i] * p;
      d4 += g4[i] * p;
      d5 += g5[i] * p;
      d6 += g6[i] * p;
      d7 += g7[i] * p;
    }
    std::size_t at = k;
    for (const double d : {d0, d1, d2, d3, d4, d5, d6, d7}) dots[at++] = d;
  }
  for (; k < lags.size(); ++k) {
    const double* g = shifted(k);
    double d = 0.0;
    for (std::size_t i = 0; i < n; ++i) d += g[i] * predicted[i];
    dots[k] = d;
  }
  return dots;
}

}  // namespace flange::diagnose
