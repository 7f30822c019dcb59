// SPDX-License-Identifier: MIT
#include "protocol.h"

#include <algorithm>
#include <cstddef>
#include <vector>

#include "criteria.h"

namespace flange::diagnose {

bool last_move_set_by_clearance(const RecordingSeries& s) {
  constexpr int kBands = criteria::kProtocolBands;
  const std::vector<bool> rest = pairs_at_rest(s.clearance_mm);
  if (rest.empty()) return false;
  const auto [lo, hi] = std::minmax_element(s.clearance_mm.begin(), s.clearance_mm.end());
  const double width = (*hi - *lo) / kBands;
  if (!(width > 0.0)) return false;
  std::vector<std::size_t> opening(kBands, 0), closing(kBands, 0);
  int last = 0;  // +1 after an opening move, -1 after a closing one, 0 before the first
  for (std::size_t i = 1; i < s.size(); ++i) {
    if (!rest[i - 1]) {
      last = s.clearance_mm[i] > s.clearance_mm[i - 1] ? 1 : -1;
      continue;
    }
    if (last == 0) continue;
    const auto band = std::min(kBands - 1, static_cast<int>((s.clearance_mm[i] - *lo) / width));
    ++(last > 0 ? opening : closing)[static_cast<std::size_t>(band)];
  }
  bool any_opening = false, any_closing = false;
  for (int b = 0; b < kBands; ++b) {
    const std::size_t up = opening[static_cast<std::size_t>(b)];
    const std::size_t down = closing[static_cast<std::size_t>(b)];
    if (up + down < criteria::kLeastSamplesPerProtocolBand) continue;
    if (static_cast<double>(std::max(up, down)) <
        criteria::kOneWayShare * static_cast<double>(up + down)) {
      return false;
    }
    any_opening = any_opening || up > down;
    any_closing = any_closing || down > up;
  }
  return any_opening && any_closing;
}

}  // namespace flange::diagnose
