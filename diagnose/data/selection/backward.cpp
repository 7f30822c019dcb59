// SPDX-License-Identifier: MIT
#include "backward.h"

#include <limits>
#include <string>
#include <vector>

#include "criteria.h"
#include "evidence.h"
#include "final_fit.h"
#include "series_statistics.h"

namespace flange::diagnose {

void remove_pick(Selection& selection, std::size_t j) {
  const Pick& pick = selection.picks[j];
  if (pick.modelled_index >= 0) {
    erase_library_effect(selection, pick.modelled_index);
  } else {
    add_free_shape(selection, *pick.chosen().free_shape, -1.0);
  }
  selection.picks.erase(selection.picks.begin() + static_cast<long>(j));
}

void drop_unneeded_picks(const Parts& parts, Selection& selection) {
  const double margin = criteria::kRemovalMargin * selection.noise_v * selection.noise_v;
  const auto refresh_error = [&] {
    selection.current_error =
        heldout_error_with(parts, selection, std::vector<bool>(selection.picks.size(), true));
  };
  refresh_error();
  while (selection.picks.size() > 1) {
    const double now = rms_of(selection.current_error);
    std::size_t least = 0;
    double least_cost = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < selection.picks.size(); ++j) {
      const double without = heldout_rms_without(parts, selection, j);
      const double cost = without * without - now * now;
      if (cost < least_cost) {
        least_cost = cost;
        least = j;
      }
    }
    if (least_cost >= margin) break;
    const std::string name = selection.picks[least].finding.name;
    selection.dropped.push_back(evidence::dropped(name, least_cost, margin));
    // Its confounding sentences said it was the one reported.
    const std::string lead = name + " and ";
    std::erase_if(selection.confounded,
                  [&](const std::string& line) { return line.starts_with(lead); });
    remove_pick(selection, least);
    refresh_error();
  }
}

}  // namespace flange::diagnose
