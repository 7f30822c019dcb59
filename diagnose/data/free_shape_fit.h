// SPDX-License-Identifier: MIT
// Shape-free families for the classes whose effect adds to the voltage as a function of one
// variable (issue 11 item 1; docs/diagnose.md, "Free shapes"): the library's formula is one
// member of each, so a recording whose effect has another shape is still named by its class.
//   nonlinearity       f(V): any continuous curve of the twin's voltage that is 0 at both ends of
//                      the part's range (a departure from the straight line, as bow and s-curve)
//   temp_offset_drift  g(T): any continuous curve of the recorded temperature
//   temp_gain_drift    (V - v_min) h(T): a gain about the range's bottom, any curve of T
// Each curve is piecewise linear between knots spread evenly over the calibration part's range
// (held constant beyond it), fitted by least squares to the gap the modelled effects leave; the
// same curve, evaluated on the held-out part's own variables, is what is scored there.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "recording_series.h"
#include "twin_replay.h"

namespace flange::diagnose {

// The library effects that have a free-shape family, in catalogue order.
const std::vector<std::string>& free_shape_effects();

struct FreeShapeFit {
  std::string effect;                 // the library effect (and so the class) it stands for
  std::string variable;               // "V", "T" or "(V - v_min) T"
  std::vector<double> knots;          // where the curve's values are given, in V or degC
  std::vector<double> values;         // the curve at the knots: V (offset, nonlinearity), 1 (gain)
  std::vector<double> cal_voltage_v;  // what it adds to the twin's voltage, calibration part
  std::vector<double> heldout_voltage_v;  // ... and held-out part
  std::map<std::string, double> params() const;  // the knot values, named by their knot
  std::string describe() const;                  // "a curve of T: -0.012 V at 21 degC, ..."
};

// Fits `effect`'s family to `cal_gap_v` (the calibration gap the modelled effects leave).
// Throws std::invalid_argument for an effect without a family.
FreeShapeFit fit_free_shape(const std::string& effect, const RecordingSeries& calibration,
                            const TwinReplay& cal_replay, const RecordingSeries& heldout,
                            const TwinReplay& ho_replay, const std::vector<double>& cal_gap_v,
                            double v_min_v);

}  // namespace flange::diagnose
