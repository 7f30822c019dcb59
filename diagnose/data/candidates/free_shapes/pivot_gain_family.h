// SPDX-License-Identifier: MIT
// A gain that changes with temperature about a pivot of its own: (V - p) h(T) = (V - v_min) h(T)
// - (p - v_min) h(T), i.e. a gain curve of T about the range's bottom plus an offset curve of T.
// Its gain part names the class; the pivot where the two curves' ratio puts it is reported.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "family.h"
#include "hats.h"

namespace flange::diagnose::free_shapes {

class PivotGainFamily : public LinearFamily {
 public:
  explicit PivotGainFamily(const RecordedPart& calibration);

  // As a curve of temperature does (CurveFamily::search).
  void search(const RecordedPart& calibration, const std::vector<double>& gap_v) override;
  std::vector<std::string> names() const override;
  Eigen::MatrixXd columns(const RecordedPart& part) const override;
  // The pivot: the voltage above v_min where the two curves cancel, by least squares over knots.
  void summarise(const Eigen::VectorXd& beta, const RecordedPart& calibration,
                 std::map<std::string, double>& params) const override;
  std::string describe(const Eigen::VectorXd& beta) const override;

 private:
  Hats hats_;
};

}  // namespace flange::diagnose::free_shapes
