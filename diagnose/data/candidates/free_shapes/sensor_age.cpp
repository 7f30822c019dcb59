// SPDX-License-Identifier: MIT
#include "sensor_age.h"

#include <algorithm>

namespace flange::diagnose::free_shapes {

std::vector<double> age_days(const RecordedPart& part) {
  std::vector<double> age(part.series.size());
  for (std::size_t i = 0; i < age.size(); ++i) {
    age[i] = std::max(
        0.0, (part.series.t_s[i] + part.replay.age_offset_s() + part.age_shift_s) / kSecondsPerDay);
  }
  return age;
}

}  // namespace flange::diagnose::free_shapes
