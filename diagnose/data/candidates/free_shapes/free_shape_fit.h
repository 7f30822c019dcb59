// SPDX-License-Identifier: MIT
// Shape-free families for the effect classes (docs/diagnose.md, "Free shapes"): the library's
// formula is one member of each, so a recording whose effect has another shape is still named by
// its class. Every family but the mains' is linear in its free values, fitted by least squares
// (with a light ridge, so near-collinear columns cannot trade huge opposite values) to the gap
// the modelled effects leave on the calibration part; the same values, evaluated on the held-out
// part's own variables, are what is scored there.
//   temp_gain_drift    (V - v_min) h(T): a gain about the range's bottom, h any curve of T
//   temp_offset_drift  g(T): any curve of the recorded temperature
//   nonlinearity       f(V): any curve of the twin's voltage, 0 at both ends of the part's range;
//                      or f(d): any curve of the reference clearance (a function of clearance
//                      alone, fine enough for a ripple of a few mm); or a periodic curve of the
//                      clearance, its period searched, repeated beyond the calibration's range
//   range_compression  over the top of the range: a surface in V and T; or h(V - k(T)) above a
//                      knee k(T) that falls as the coil heats (searched), h any curve; when its
//                      change with T does not earn its place either names a nonlinearity alike,
//                      and is named the nonlinearity if it raises the top (no compression does)
//   thermal_lag        dV/dT (S T - T): the coil at a temperature S T other than the recorded T,
//                      S any mix of first-order lags (the sensor lags: a mean delay tau_s > 0) and
//                      of advances of the recorded temperature (the reading lags: tau_s < 0)
//   channel_skew       s(t) dV/dt: the voltage channel off in time by a skew that may drift
//                      through the session (a quadratic in time)
//   mains_pickup       lines at the aliases of 50/60 Hz and their harmonics found on the
//                      calibration part, amplitude and phase free in short windows of each part
//                      (fitted on the held-out part's own gap: heldout_values says how many),
//                      with each part's own constant where a harmonic aliases to 0 Hz
//   ageing_drift       a trend in the sensor's age, carried across sessions by their start times:
//                      continuing (an offset and a line or a logarithmic settling, its curvature
//                      chosen on the held-out level where the calibration leaves it open), or
//                      settled (any curve of age over the calibration session, held after it),
//                      or a line over the calibration session held after it and a level between
//                      the sessions chosen on the held-out part
// Curves of one variable are piecewise linear between knots spread evenly over the calibration
// part's range (held constant beyond it). Each family is one file of this folder (family.h says
// what a family does); the classes' fits (candidates/class_fits.cpp) say which family stands for
// which class and how to make it (family_makers.h).
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "recorded_part.h"

namespace flange::diagnose {

namespace free_shapes {
class Family;
}  // namespace free_shapes

// Makes a family's shape for a calibration part (family_makers.h).
using MakeFreeShape = std::unique_ptr<free_shapes::Family> (*)(const RecordedPart& calibration);

// One family: the library effect (and so the class) it stands for, its variable and how to make
// it.
struct FreeShapeFamily {
  std::string effect;
  std::string variable;  // "T", "(V - v_min) T", "V", "d", "lagged T", "t", "age, continuing", ...
  MakeFreeShape make = nullptr;
  // Whether it is weighed where the recorded voltages lie on a converter grid (the class table
  // says why not, where not).
  bool weighed_on_a_converter_grid = true;
  // The class a curve of this family may equally be when a curve of the voltage alone follows it
  // over the top of the recorded voltages (identify/fixed_knees.h, judge_curves_over_the_top);
  // empty for none.
  std::string over_the_top_also_of = {};
  // The class a curve of this family may equally be when a curve of the recorded temperature
  // alone follows it (identify/gains_alike_offsets.h: a gain about a pivot far off the recorded
  // voltages); empty for none.
  std::string temperature_alone_also_of = {};
};

// Every family, in the order they are scored (the class table's, classes/effect_classes.h).
const std::vector<FreeShapeFamily>& free_shape_families();

struct FreeShapeFit {
  FreeShapeFamily family;
  std::map<std::string, double> params;   // the free values, named, plus the class's summary
  std::string description;                // "a free curve of T through -0.012 at 21 degC, ..."
  std::vector<double> cal_voltage_v;      // what it adds to the twin's voltage, calibration part
  std::vector<double> heldout_voltage_v;  // ... and held-out part
  // Values fitted on the held-out part itself (the mains' windows and a session's constant; an
  // ageing's held-out age when the clocks do not say it, or its settling's curvature when they do;
  // 0 for the others): fitting them to white noise alone would lower its mean square by
  // heldout_values / n of its variance.
  int heldout_values = 0;
  // How many values the calibration fit chose (the curve's, plus a searched law's): what the
  // selection weighs when two candidates gain alike.
  int free_values = 0;
  // For each free value of a linear family: how far the calibration part's fitted voltage moves
  // per unit of it once the family's other values compensate, V RMS (identify/
  // compensated_sensitivity.h), over both parts where the held-out part told them
  // (LinearFamily::values_told_by_heldout);
  // 0 for a value nothing in the data moves with (a knot at a temperature never visited). Empty
  // for the mains' lines.
  std::map<std::string, double> value_sensitivity_v;
  // Summary parameters whose search ended on an edge of its range: key -> "<= x" or ">= x"
  // (LinearFamily::search_edges).
  std::map<std::string, std::string> search_edges;
  // The other class a shape is alike: a range compression's family whose knee (or surface) does
  // not move with temperature is a curve of V alone above a fixed voltage, which no data tell
  // from a static nonlinearity of V (identify/fixed_knees.h). Lowering the top, it keeps the
  // compression's name and this is the nonlinearity; raising it, it is named the nonlinearity
  // and this is the compression. Empty for every other shape.
  std::string also_of_class;
};

// What a family is fitted to: the two parts, the gap the modelled effects leave on each, and
// whether the held-out part's age is unknown (its clock restarts at 0 and no start times were
// given).
struct FreeShapeInputs {
  RecordedPart calibration, heldout;
  const std::vector<double>& cal_gap_v;
  const std::vector<double>& ho_gap_v;
  bool heldout_age_unknown = false;
  // Whether no effect picked so far can carry a level from the calibration session to the
  // held-out one (none picked, or only classes whose effect has no level of its own:
  // EffectClass::carries_no_level), so that a level on the held-out gap that the calibration
  // session does not show can only be a change between the sessions
  // (AgeingFamily::choose_on_heldout).
  bool no_level_carried = false;
};

// Fits `family` to `in.cal_gap_v` (the calibration gap the modelled effects leave);
// `in.ho_gap_v`, the held-out gap they leave, is read only by the families with heldout_values.
// With `in.heldout_age_unknown`, a family of the sensor's age places the held-out part at the
// age, before or after the calibration session, that fits its gap best (docs/diagnose.md,
// "Sessions and time").
FreeShapeFit fit_free_shape(const FreeShapeFamily& family, const FreeShapeInputs& in);

}  // namespace flange::diagnose
