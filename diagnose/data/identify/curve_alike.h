// SPDX-License-Identifier: MIT
// Whether a curve of one recorded variable alone follows a pick's curve as closely as the data
// can tell (docs/diagnose.md, "Indistinguishable classes"): the test behind a compression's curve
// over the top alike a nonlinearity of V (fixed_knees.h) and a gain alike an offset curve of the
// temperature (gains_alike_offsets.h).
#pragma once

#include <optional>
#include <vector>

namespace flange::diagnose {

// A curve of x (piecewise linear on `knots` knots spread evenly over the calibration part's x,
// held beyond them; fitted by least squares to `cal_curve`, what the pick adds to the twin's
// voltage on the calibration part) where it comes within criteria::kConfoundingMargin of
// noise_v^2 of `cal_curve` (mean square) and, on the held-out samples given (`ho_x`, the pick's
// `ho_curve` there and `ho_left`, what the pick leaves of the held-out gap), leaves at most that
// much more of the gap than the pick: its values on the calibration samples. Nothing where it does
// not, for sizes that differ, fewer than two samples or knots, or an x that does not vary.
std::optional<std::vector<double>> curve_of_one_variable_alike(
    const std::vector<double>& cal_x, const std::vector<double>& cal_curve,
    const std::vector<double>& ho_x, const std::vector<double>& ho_curve,
    const std::vector<double>& ho_left, double noise_v, int knots);

}  // namespace flange::diagnose
