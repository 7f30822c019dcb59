// SPDX-License-Identifier: MIT
// A compression of the top of the range that depends on temperature: any curve of V over the top
// two fifths of the calibration part's voltage range (0 below it), times any curve of T (three
// knots): f(V, T) = sum c_jk hat_j(V) hat_k(T).
#pragma once

#include <string>
#include <vector>

#include "family.h"
#include "hats.h"

namespace flange::diagnose::free_shapes {

class CompressionSurfaceFamily : public LinearFamily {
 public:
  explicit CompressionSurfaceFamily(const RecordedPart& calibration);

  // Whether the surface's change with temperature earns its place: the same surface held equal
  // at every temperature (a curve of V alone) is fitted too, and must leave
  // kLeastShareForATemperatureDependence more of the calibration gap's sum of squares.
  void search(const RecordedPart& calibration, const std::vector<double>& gap_v) override;
  // A surface that does not change with temperature is a curve of V alone over the top of the
  // range: a static nonlinearity, not a range compression (whose class is temperature dependent).
  bool shape_is_function_of_clearance_alone() const override { return !temperature_matters_; }
  std::vector<std::string> names() const override;
  Eigen::MatrixXd columns(const RecordedPart& part) const override;
  std::string describe(const Eigen::VectorXd& beta) const override;

  bool temperature_matters() const { return temperature_matters_; }

 private:
  Hats volt_, temp_;
  bool temperature_matters_ = true;
};

}  // namespace flange::diagnose::free_shapes
