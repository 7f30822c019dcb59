// SPDX-License-Identifier: MIT
// What a free-shape family is to the fit (free_shape_fit.h): it searches what its shape depends
// on (a skew's law, a knee, a ripple's period, the mains' lines) on the calibration gap, then fits
// its free values. Every family but the mains' is linear in its values and shares one fit
// (LinearFamily): columns on each part, the ridge least squares (ridge_solve.h) on the
// calibration gap, the same values evaluated on the held-out part's own variables.
#pragma once

#include <Eigen/Dense>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "criteria.h"
#include "free_shape_fit.h"
#include "recorded_part.h"

namespace flange::diagnose::free_shapes {

// Whether a shape's change with temperature earns its place (the compression surface's, the
// moving knee's): the same shape held equal at every temperature must leave this share more of
// the calibration gap's sum of squares. Where the fit leaves the noise, that sum is n sigma^2,
// so the share asks of the change with temperature what a pick must gain on held-out data
// (criteria::kScoreResolution, per sample): a change the score could not resolve does not name
// the temperature-dependent class. It compares two fits of the calibration part, nested (the
// shape without its change is a member of the shape with it), a role of its own.
inline constexpr double kLeastShareForATemperatureDependence = criteria::kScoreResolution;

class Family {
 public:
  virtual ~Family() = default;
  // Families with parameters their shape depends on search them here first, on the calibration
  // part's gap.
  virtual void search(const RecordedPart& /*calibration*/, const std::vector<double>& /*gap_v*/) {}
  // After search(): the free values fitted, what the shape adds on each part, its description.
  // The family (FreeShapeFit::family) is the caller's to set.
  virtual FreeShapeFit fit(const FreeShapeInputs& in) = 0;
  // Whether the fitted shape is a function of the clearance alone (a compression that does not
  // change with temperature is a curve of V alone): it then names the class the table marks as
  // such (EffectClass::function_of_clearance_alone), not its own.
  virtual bool shape_is_function_of_clearance_alone() const { return false; }
};

// A family linear in its free values.
class LinearFamily : public Family {
 public:
  // The ridge least squares of columns(calibration) on the calibration gap, evaluated on the
  // held-out part; the held-out choice (choose_on_heldout) first, or the held-out part's place
  // in the sensor's age after (follows_the_sensors_age) where the clocks do not say it.
  FreeShapeFit fit(const FreeShapeInputs& in) final;

  // The free values' names, one per column.
  virtual std::vector<std::string> names() const = 0;
  // How many values search() chose.
  virtual int searched_values() const { return 0; }
  virtual Eigen::MatrixXd columns(const RecordedPart& part) const = 0;
  // The class's summary parameters (a lag's mean delay, a skew's mean) beside the free values.
  virtual void summarise(const Eigen::VectorXd& /*beta*/, const RecordedPart& /*calibration*/,
                         std::map<std::string, double>& /*params*/) const {}
  virtual std::string describe(const Eigen::VectorXd& beta) const = 0;
  // The summary parameters whose search ended on an edge of its range, where the data may hold
  // the value beyond it: key -> "<= x" or ">= x", reported as a bound rather than a value.
  virtual std::map<std::string, std::string> search_edges() const { return {}; }
  // Families whose shape the calibration part leaves open where the held-out part lies choose it
  // there, after search(): returns how many values that fitted on the held-out part, with a
  // phrase for the description.
  // `no_level_carried`: FreeShapeInputs::no_level_carried.
  virtual int choose_on_heldout(const RecordedPart& /*calibration*/,
                                const std::vector<double>& /*cal_gap*/,
                                const RecordedPart& /*heldout*/,
                                const std::vector<double>& /*ho_gap*/, bool /*no_level_carried*/,
                                std::string& /*how*/) {
    return 0;
  }
  // The free values themselves where choose_on_heldout chose them (in names() order) rather
  // than the calibration part's least squares.
  virtual std::optional<Eigen::VectorXd> values_chosen_on_heldout() const { return std::nullopt; }
  // Whether values chosen on the held-out part are told by it (a level between the sessions, which
  // the calibration part does not move at all): their sensitivity is then over both parts. A
  // settling's rate chosen on the held-out level is not: one level cannot tell the rate from the
  // curvature, and it stays `undetermined`.
  virtual bool values_told_by_heldout() const { return false; }
  // Whether the shape is a curve of the sensor's age: where the held-out clock does not say the
  // held-out part's age, it is placed where the curve fits it (heldout_age.h).
  virtual bool follows_the_sensors_age() const { return false; }
};

}  // namespace flange::diagnose::free_shapes
