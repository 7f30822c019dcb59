// SPDX-License-Identifier: MIT
// A periodic curve of the clearance: any shape over one period (kRippleKnots hats on a circle of
// phase d / P), the period P searched. A micrometer's lead screw or a target's machining marks
// repeat with the clearance; a curve of the clearance (CurveFamily) follows such a ripple within
// the calibration's range but is held or continued along a line beyond it, where a held-out
// session that goes a millimetre further meets the next periods. This family carries the ripple
// there.
#pragma once

#include <Eigen/Dense>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "family.h"

namespace flange::diagnose::free_shapes {

class RippleFamily : public LinearFamily {
 public:
  // The period, over frequencies from two periods across the calibration's range to one per
  // kShortestRippleMm, on a lattice fine enough that the phase drifts by at most a quarter period
  // across the range (grid_search.h), then by golden section about the best.
  void search(const RecordedPart& calibration, const std::vector<double>& gap_v) override;
  std::vector<std::string> names() const override;
  int searched_values() const override { return 1; }
  Eigen::MatrixXd columns(const RecordedPart& part) const override;
  void summarise(const Eigen::VectorXd& beta, const RecordedPart& calibration,
                 std::map<std::string, double>& params) const override;
  std::string describe(const Eigen::VectorXd& beta) const override;
  // The period, when the search ended on the longest (two across the range) or the shortest.
  std::map<std::string, std::string> search_edges() const override;

  // The period searched, mm (0 before a search, or where the range is too short for one).
  double period_mm() const { return per_mm_ > 0.0 ? 1.0 / per_mm_ : 0.0; }

  // Eight hats over a period: a ripple's shape up to its fourth harmonic.
  static constexpr int kRippleKnots = 8;
  // The shortest period searched: the pitch of a metric micrometer's spindle, the finest repeat
  // its lead screw makes.
  static constexpr double kShortestRippleMm = 0.5;

 private:
  // The hat left of clearance `d`'s phase and the weight of the one right of it.
  static std::pair<Eigen::Index, double> place(double d, double per_mm);
  // The sum of squares the ripple of frequency `per_mm` leaves of `gap`.
  static double fitted_sse(const std::vector<double>& d, const std::vector<double>& gap,
                           double per_mm);

  double per_mm_ = 0.0;
  double first_per_mm_ = 0.0, last_per_mm_ = 0.0, step_per_mm_ = 0.0;  // the search's range
};

}  // namespace flange::diagnose::free_shapes
