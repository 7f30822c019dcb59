// SPDX-License-Identifier: MIT
// Where a run's values lie: the median, and the half-sample mode (Bickel and Fruehwirth 2006),
// the middle of the densest stretch, which a minority of values far off (a wheelset's shift in
// the curves of one hand) does not move.
#pragma once

#include <vector>

namespace flange::host {

// The median of `values` (at least one).
double median(std::vector<double> values);

// The half-sample mode of `values` (at least one; finite): the shortest stretch holding half of
// them, halved again until two or three values remain, and their middle. It lies in a cluster
// holding more than half the values whenever the rest are further from it than its own spread.
double half_sample_mode(std::vector<double> values);

}  // namespace flange::host
