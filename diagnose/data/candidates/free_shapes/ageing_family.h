// SPDX-License-Identifier: MIT
// A trend in the sensor's age that goes on after the calibration session: an offset plus either
// a straight line in age (the library's) or a settling a ln(1 + age / tau), with tau searched from
// three minutes to ten days on the calibration gap. Age in days from the calibration part's start
// (the held-out part's by its start time, or the same start when that is unknown: sensor_age.h).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "family.h"

namespace flange::diagnose::free_shapes {

class AgeingFamily : public LinearFamily {
 public:
  void search(const RecordedPart& calibration, const std::vector<double>& gap_v) override;
  // Where the start times place the held-out session days after a short calibration session, a
  // settling's curvature decides the level there, and the calibration part barely shows it. The
  // calibration part keeps the settlings it does not reject (a sum of squares within
  // kSettlingLeeway sigma^2 of its best); of those, the one whose carried-on level fits the
  // held-out gap best is taken: one value fitted there.
  int choose_on_heldout(const RecordedPart& calibration, const std::vector<double>& cal_gap,
                        const RecordedPart& heldout, const std::vector<double>& ho_gap,
                        std::string& how) override;
  std::vector<std::string> names() const override;
  // The settling time, when its search ended on the longest or the shortest one searched.
  std::map<std::string, std::string> search_edges() const override;
  int searched_values() const override { return 1; }
  Eigen::MatrixXd columns(const RecordedPart& part) const override;
  void summarise(const Eigen::VectorXd& beta, const RecordedPart& calibration,
                 std::map<std::string, double>& params) const override;
  std::string describe(const Eigen::VectorXd& beta) const override;
  bool follows_the_sensors_age() const override { return true; }

  // The settling's time constant chosen, days (0: the straight line).
  double settling_tau_days() const { return tau_days_; }
  // The settlings searched: 0 is the straight line; then tau from three minutes to ten days, a
  // factor of 1.5 apart.
  static std::vector<double> taus();

 private:
  static std::string describe_tau(double tau_days);

  double tau_days_ = 0.0, chosen_ = 0.0;
};

}  // namespace flange::diagnose::free_shapes
