// SPDX-License-Identifier: MIT
// The voltage channel sampled skew(t) = s0 + s1 h + s2 h^2 off (h in hours from the session's
// start): the twin's voltage at t + skew(t), by linear interpolation (the library's channel_skew
// sign: negative when the voltage is late). A DAQ clock that drifts, or drifts and settles. The
// law is searched on the calibration gap (grid_search.h: a lattice in s0 and s1, then a pattern
// search in all three), since a skew of seconds across a move of the micrometer is far from a
// small perturbation; one column with a free scale then carries it.
#pragma once

#include <array>
#include <map>
#include <string>
#include <vector>

#include "family.h"

namespace flange::diagnose::free_shapes {

class SkewFamily : public LinearFamily {
 public:
  void search(const RecordedPart& calibration, const std::vector<double>& gap_v) override;
  std::vector<std::string> names() const override { return {"scale"}; }
  int searched_values() const override { return 3; }
  Eigen::MatrixXd columns(const RecordedPart& part) const override;
  void summarise(const Eigen::VectorXd& beta, const RecordedPart& calibration,
                 std::map<std::string, double>& params) const override;
  std::string describe(const Eigen::VectorXd& beta) const override;

  // The law searched: s0 (s), s1 (s/h), s2 (s/h^2).
  const std::array<double, 3>& law() const { return law_; }
  // What sampling the twin's voltage skew(t) off adds to it.
  static std::vector<double> shift(const RecordedPart& part, const std::array<double, 3>& law);

  // The library's own skew range, and a drift that can double it within a bench session.
  static constexpr double kMaxSkewS = 10.0;
  static constexpr double kMaxDriftSPerHour = 10.0;

 private:
  double skew_at(double hours) const { return law_[0] + law_[1] * hours + law_[2] * hours * hours; }

  std::array<double, 3> law_ = {0.0, 0.0, 0.0};
};

}  // namespace flange::diagnose::free_shapes
