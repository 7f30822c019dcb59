// SPDX-License-Identifier: MIT
// Whether a curve of one recorded variable alone follows a pick's curve as closely as the data
// can tell (docs/diagnose.md, "Indistinguishable classes"): the test behind a compression's curve
// over the top alike a nonlinearity of V (fixed_knees.h) and a gain alike an offset curve of the
// temperature (gains_alike_offsets.h).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "parts.h"
#include "selection.h"

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

// A pick's curve on the held-out samples within the calibration part's ranges (beyond them each
// curve is continued or held as its family does, which no data decide), beside the variable `x`
// there and what the pick leaves of the held-out gap.
struct HeldoutCurve {
  std::vector<double> x, curve, left;
};

// Whether a pick's free shape (its curve on the calibration part: FreeShapeFit::cal_voltage_v),
// with its HeldoutCurve, is alike the other class.
using CurveIsAlike = std::function<bool(const FreeShapeFit& shape, const HeldoutCurve& heldout)>;

// Each pick with a free shape whose family names, in `other_of`, a class the pick does not name
// yet, and whose curve `is_alike` (on the held-out part's variable `heldout_x`), names that class
// in its indistinguishable_from (last). Returns the indices of the picks it named it in.
std::vector<std::size_t> name_classes_alike(const Parts& parts, Selection& selection,
                                            std::string FreeShapeFamily::*other_of,
                                            const std::vector<double>& heldout_x,
                                            const CurveIsAlike& is_alike);

}  // namespace flange::diagnose
