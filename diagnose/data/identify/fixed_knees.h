// SPDX-License-Identifier: MIT
// A compression whose knee does not move and a static nonlinearity of V (docs/diagnose.md,
// "Confidence"): above a knee that stays put over the recorded temperatures, a range
// compression's family fits a curve of the voltage alone, which a static nonlinearity of V makes
// as well; no data of these temperatures can tell the two apart, and the pick names both (the
// compression first where the curve lowers the top, as a compression does: fit_free_shape).
#pragma once

#include <string>
#include <vector>

#include "parts.h"
#include "selection.h"

namespace flange::diagnose {

// Each pick whose free shape a range compression's family made with a knee or surface that did
// not move with temperature (FreeShapeFit::also_of_class: the class the pick does not name, the
// compression's or the nonlinearity's) names that class in its indistinguishable_from (criteria::kMostConfidenceOfIndistinguishable then
// bounds its confidence).
void judge_fixed_knees(Selection& selection);

// Whether `curve` (what a pick adds to the twin's voltage on each part, beside the twin's voltage
// `v` of each part; `ho_left`, what the pick leaves of the held-out gap) is a curve of the
// voltage alone that a fixed-knee compression makes: a piecewise-linear curve of v on `knots`
// knots over the calibration part's voltages, fitted to the calibration curve, comes within
// criteria::kConfoundingMargin of noise_v^2 of it (mean square) on the calibration part and
// leaves at most that much more of the held-out gap than the pick (the held-out samples given),
// moves the lower half of the calibration voltages by at most
// criteria::kMostLowerHalfShareOfACompression of what it moves the upper half, and lowers the
// upper half.
bool is_a_curve_over_the_top(const std::vector<double>& cal_v, const std::vector<double>& cal_curve,
                             const std::vector<double>& ho_v, const std::vector<double>& ho_curve,
                             const std::vector<double>& ho_left, double noise_v, int knots);

// Each pick whose free shape's family names a class it may equally be over the top of the
// voltages (FreeShapeFamily::over_the_top_also_of: the nonlinearity's curve of the clearance, a
// range compression) and is_a_curve_over_the_top (on the twin's voltage, with as many knots as the
// curve has values, on the held-out samples within the calibration part's ranges) names that class
// in its indistinguishable_from and names it first (name_the_compression_first).
void judge_curves_over_the_top(const Parts& parts, Selection& selection);

// A pick whose curve judge_curves_over_the_top found over the top of the voltages (the class
// its family names there, the compression, last in its indistinguishable_from) is named that
// class first, with its own class as the one alike: such a curve leaves the lower half of the
// voltages and lowers the top, what a compression does, as a compression family's curve of the
// voltage alone that lowers the top keeps the compression's name (free_shape_fit.cpp).
// criteria::kMostLowerHalfShareOfACompression says why.
void name_the_compression_first(Pick& pick);

// Both of the above: the families' fixed knees, then the curves of the clearance over the top.
void judge_fixed_knees(const Parts& parts, Selection& selection);

// What would tell the pick's curve from a compression of the class `other`: a session that holds
// the clearance where the voltage lies above the knee while the temperature goes beyond the
// recorded range (a compression's knee may move there, a nonlinearity of V does not); or, where
// the recordings already span the bench's operating range, that no session of it would.
std::string tell_fixed_knee_from_compression(const Parts& parts, const EffectFinding& pick,
                                             const std::string& other);

}  // namespace flange::diagnose
