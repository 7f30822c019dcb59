// SPDX-License-Identifier: MIT
// A free curve of one variable through hats (hats.h): an offset that is any curve of the
// recorded temperature, a gain about the range's bottom that is any curve of it, any curve of the
// twin's voltage (0 at both ends of the part's range), of the reference clearance, or of the
// sensor's age over the calibration session (held after it).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "family.h"
#include "hats.h"

namespace flange::diagnose::free_shapes {

// What the curve is of.
enum class CurveOf {
  kTemperature,        // g(T): an offset
  kGainOfTemperature,  // (V - v_min) h(T): a gain about the range's bottom
  kVoltage,            // f(V), 0 at both ends of the calibration part's range
  kClearance,          // f(d), fine enough for a ripple of a few mm
  kAge,                // any curve of age over the calibration session, held after it
};

class CurveFamily : public LinearFamily {
 public:
  // `knots`: a curve of temperature's (kKnots, or kFineKnots refitted finer).
  CurveFamily(CurveOf of, const RecordedPart& calibration, int knots = kKnots);

  // Curves of clearance and of temperature go on past an end as far as the calibration part says
  // (choose_reach): a curve of clearance held or going on kClearanceReachMm, a curve of
  // temperature going on one knot spacing or further.
  void search(const RecordedPart& calibration, const std::vector<double>& gap_v) override;
  std::vector<std::string> names() const override;
  Eigen::MatrixXd columns(const RecordedPart& part) const override;
  std::string describe(const Eigen::VectorXd& beta) const override;
  bool follows_the_sensors_age() const override { return of_ == CurveOf::kAge; }

  const Hats& hats() const { return hats_; }

 private:
  double variable_at(const RecordedPart& part, const std::vector<double>& age, std::size_t i) const;

  CurveOf of_;
  Hats hats_;
  std::vector<std::size_t> used_;
};

}  // namespace flange::diagnose::free_shapes
