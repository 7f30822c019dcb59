// SPDX-License-Identifier: MIT
#include "reprofiling_search.h"

#include <algorithm>

namespace flange::host {

std::vector<std::size_t> find_reprofilings(const std::vector<double>& left,
                                           const std::vector<double>& right, double max_step_mm) {
  std::vector<std::size_t> found;
  const std::size_t n = std::min(left.size(), right.size());
  for (std::size_t k = 1; k < n; ++k) {
    const double before = (left[k - 1] + right[k - 1]) / 2.0;
    const double after = (left[k] + right[k]) / 2.0;
    if (before - after > max_step_mm) found.push_back(k);
  }
  return found;
}

}  // namespace flange::host
