// SPDX-License-Identifier: MIT
// The filtered clearance over a run in three numbers: where it ended and how far it went each
// way once the filter had settled (its start-up from the core's zero state is no clearance).
#pragma once

#include <algorithm>
#include <limits>
#include <optional>

namespace flange::host {

struct FilteredExtent {
  std::optional<double> last_mm;  // the last row's filter output; none before any row
  double min_mm = std::numeric_limits<double>::infinity();   // +inf: no settled row
  double max_mm = -std::numeric_limits<double>::infinity();  // -inf: no settled row

  // One row's filter output; `settled`: past the start-up transient (RunSummary::settle_samples).
  void add(double filt_mm, bool settled) {
    last_mm = filt_mm;
    if (!settled) return;
    min_mm = std::min(min_mm, filt_mm);
    max_mm = std::max(max_mm, filt_mm);
  }
  bool has_settled_rows() const { return min_mm <= max_mm; }
};

}  // namespace flange::host
