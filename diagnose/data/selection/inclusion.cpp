// SPDX-License-Identifier: MIT
#include "inclusion.h"

#include <limits>

#include "final_fit.h"
#include "parallel_work.h"

namespace flange::diagnose {
namespace {

// The share of resamples on which the final fit without each pick leaves more than with it; each
// pick's replay and resamples a piece of parallel work.
void measure_need_in_final_fit(const Parts& parts, Selection& selection) {
  const std::vector<bool> all(selection.picks.size(), true);
  const std::vector<double> with_all =
      selection.resamples.mean_squares(heldout_error_with(parts, selection, all));
  const std::vector<double> shares =
      parallel_map<double>(selection.picks.size(), [&](std::size_t j) {
        std::vector<bool> kept = all;
        kept[j] = false;
        const std::vector<double> without =
            selection.resamples.mean_squares(heldout_error_with(parts, selection, kept));
        int needed = 0;
        for (std::size_t r = 0; r < without.size(); ++r) needed += without[r] > with_all[r] ? 1 : 0;
        return static_cast<double>(needed) / static_cast<double>(selection.resamples.size());
      });
  for (std::size_t j = 0; j < shares.size(); ++j) selection.picks[j].finding.inclusion = shares[j];
}

}  // namespace

double share_of_wins(const Step& step, const std::vector<double>& before,
                     const BlockResamples& resamples) {
  const std::vector<double> base = resamples.mean_squares(before);
  std::vector<std::vector<double>> after;
  for (const Candidate& c : step.candidates) {
    after.push_back(resamples.mean_squares(c.heldout_error));
  }
  int wins = 0;
  for (std::size_t r = 0; r < resamples.size(); ++r) {
    std::size_t arg = 0;
    double best = -std::numeric_limits<double>::infinity();
    for (std::size_t c = 0; c < step.candidates.size(); ++c) {
      const double gain = base[r] - after[c][r];
      if (gain > best) {
        best = gain;
        arg = c;
      }
    }
    // The claim is the class: a win of another member of the chosen one's class (its library
    // formula, another free family) would name it again.
    const std::string& won = step.candidates[arg].fit.settings.name;
    if (best > 0.0 && won == step.candidates[step.chosen].fit.settings.name) ++wins;
  }
  return static_cast<double>(wins) / static_cast<double>(resamples.size());
}

void measure_inclusion(const Parts& parts, Selection& selection) {
  if (selection.shapes_refined) {
    measure_need_in_final_fit(parts, selection);
    return;
  }
  const std::vector<Pick>& picks = selection.picks;
  const std::vector<double> shares = parallel_map<double>(picks.size(), [&](std::size_t s) {
    const std::vector<double>& before =
        s == 0 ? selection.ho_gap : picks[s - 1].chosen().heldout_error;
    return share_of_wins(picks[s].step, before, selection.resamples);
  });
  for (std::size_t s = 0; s < shares.size(); ++s) selection.picks[s].finding.inclusion = shares[s];
}

}  // namespace flange::diagnose
