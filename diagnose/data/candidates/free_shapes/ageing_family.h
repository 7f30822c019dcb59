// SPDX-License-Identifier: MIT
// A trend in the sensor's age that goes on after the calibration session: an offset plus either
// a straight line in age (the library's) or a settling a ln(1 + age / tau), with tau searched from
// three minutes to ten days on the calibration gap. Age in days from the calibration part's start
// (the held-out part's by its start time, or the same start when that is unknown: sensor_age.h).
#pragma once

#include <map>
#include <optional>
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
  // held-out gap best is taken: one value fitted there. Its rate (or size) likewise: a session
  // of an hour barely shows a rate that moves the level by the noise over days, so the rate the
  // held-out level asks for is taken as far as the calibration part allows it (its sum of
  // squares within the same leeway): a second value fitted there. Only while no pick can carry a
  // level (FreeShapeInputs::no_level_carried): after effects fitted on the calibration part, a
  // level left on the held-out part is as likely their error carried beyond the calibration
  // session (a temperature law continued to other temperatures) as a change between the
  // sessions, and the held-out part cannot tell them apart.
  int choose_on_heldout(const RecordedPart& calibration, const std::vector<double>& cal_gap,
                        const RecordedPart& heldout, const std::vector<double>& ho_gap,
                        bool no_level_carried, std::string& how) override;
  std::optional<Eigen::VectorXd> values_chosen_on_heldout() const override;
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
  // The calibration gap's least squares on [1, column] at the present settling.
  struct Profile {
    double mean_column, mean_gap, spread, rate, least_sse;
  };
  // A settling's rate chosen on the held-out level (beside the calibration part's own), its
  // offset from the calibration part.
  struct Trial {
    double tau, rate, calibration_rate, offset, ho_sse;
  };
  static std::string describe_tau(double tau_days);
  // The description's note on a settling chosen on the held-out level ("" for the calibration's).
  std::string curvature_note() const;
  // The settling alone chosen on the held-out level, each one's values the calibration part's.
  int choose_settling(const RecordedPart& calibration, const std::vector<double>& cal_gap,
                      const RecordedPart& heldout, const std::vector<double>& ho_gap,
                      std::string& how);
  std::vector<double> column_of(const std::vector<double>& ages) const;
  static Profile profile(const std::vector<double>& column, const std::vector<double>& cal_gap);
  Trial heldout_trial(const Profile& p, double cal_bound, const std::vector<double>& ho_column,
                      const std::vector<double>& ho_gap) const;

  double tau_days_ = 0.0, chosen_ = 0.0;
  std::optional<Eigen::Vector2d> heldout_level_;  // offset and rate chosen on the held-out part
};

}  // namespace flange::diagnose::free_shapes
