// SPDX-License-Identifier: MIT
// The sensor's age at every sample of a part, as the families of its age read it.
#pragma once

#include <vector>

#include "recorded_part.h"

namespace flange::diagnose::free_shapes {

inline constexpr double kSecondsPerDay = 86400.0;
inline constexpr double kSecondsPerHour = 3600.0;

// The sensor's age at every sample, in days from the calibration part's start: the held-out
// part's by its start time, or the same start when that is unknown (docs/diagnose.md, "Sessions
// and time"), moved by the part's age_shift_s; never below 0.
std::vector<double> age_days(const RecordedPart& part);

}  // namespace flange::diagnose::free_shapes
