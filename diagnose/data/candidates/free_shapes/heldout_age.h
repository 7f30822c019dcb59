// SPDX-License-Identifier: MIT
// Where a held-out session lies in the sensor's age when its clock restarts at 0 and no start
// times say it (docs/diagnose.md, "Sessions and time").
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "family.h"
#include "free_shape_fit.h"
#include "recorded_part.h"

namespace flange::diagnose::free_shapes {

// The shift, from 30 days before the calibration session's start to 30 days after its end, at
// which `shape` with values `beta` best fits the held-out gap `ho_gap_v`: `fit`'s held-out
// voltage is the shape there, with one value fitted on the held-out part (charged like the
// mains' windows), the shift in its params and its description.
void place_heldout_age(const LinearFamily& shape, const Eigen::VectorXd& beta,
                       const RecordingSeries& calibration, const RecordedPart& heldout,
                       const std::vector<double>& ho_gap_v, FreeShapeFit& fit);

}  // namespace flange::diagnose::free_shapes
