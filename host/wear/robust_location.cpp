// SPDX-License-Identifier: MIT
#include "robust_location.h"

#include <algorithm>
#include <cstddef>

namespace flange::host {

double median(std::vector<double> values) {
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  if (values.size() % 2 == 1) return *middle;
  return (*middle + *std::max_element(values.begin(), middle)) / 2.0;
}

double half_sample_mode(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  std::size_t from = 0, count = values.size();
  while (count > 3) {
    const std::size_t half = (count + 1) / 2;
    std::size_t best = from;
    for (std::size_t i = from; i + half <= from + count; ++i) {
      if (values[i + half - 1] - values[i] < values[best + half - 1] - values[best]) best = i;
    }
    from = best;
    count = half;
  }
  if (count == 3) {
    const double low = values[from + 1] - values[from], high = values[from + 2] - values[from + 1];
    if (low < high) return (values[from] + values[from + 1]) / 2.0;
    if (high < low) return (values[from + 1] + values[from + 2]) / 2.0;
    return values[from + 1];
  }
  if (count == 2) return (values[from] + values[from + 1]) / 2.0;
  return values[from];
}

}  // namespace flange::host
