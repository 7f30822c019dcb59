// SPDX-License-Identifier: MIT
// An ageing whose curve the calibration session does not show: a line in the sensor's age over
// the calibration session, held at its end after it, and a level between the sessions chosen on
// the held-out part. An ageing that is any monotone curve of the age (it may speed up, or settle
// faster than any settling the calibration part allows) shows mostly as that level when the
// held-out session is hours to days later: neither the line nor the settlings of the continuing
// family (ageing_family.h) carry the calibration session's own slope to it.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "family.h"

namespace flange::diagnose::free_shapes {

class AgeingLevelFamily : public LinearFamily {
 public:
  // Keeps the calibration session's last age, after which the line is held.
  void search(const RecordedPart& calibration, const std::vector<double>& gap_v) override;
  // Where the start times place the held-out session after the calibration session, and no pick
  // can carry a level (the reason is AgeingFamily::choose_on_heldout's: after effects fitted on
  // the calibration part a held-out level may be their carry-over), the level between the sessions
  // is the held-out gap's mean less the line's end: one value fitted on the held-out part. The
  // mean is over the held-out samples within the calibration part's clearance and temperature
  // ranges when a quarter or more lie there (criteria::kLeastShareWithinReach, the verdict's
  // share): beyond them the other effects' curves are held or continued, and what they miss
  // there is no change between the sessions
  // (AltSelftest.AGapExplainedWithinReachIsLeftOnlyBeyondTheTwinsFits).
  int choose_on_heldout(const RecordedPart& calibration, const std::vector<double>& cal_gap,
                        const RecordedPart& heldout, const std::vector<double>& ho_gap,
                        bool no_level_carried, std::string& how) override;
  std::optional<Eigen::VectorXd> values_chosen_on_heldout() const override { return chosen_; }
  std::vector<std::string> names() const override;
  Eigen::MatrixXd columns(const RecordedPart& part) const override;
  std::string describe(const Eigen::VectorXd& beta) const override;
  bool values_told_by_heldout() const override { return true; }
  bool follows_the_sensors_age() const override { return true; }

 private:
  double end_age_days_ = 0.0;
  std::optional<Eigen::VectorXd> chosen_;  // offset, rate and level chosen with the held-out part
};

}  // namespace flange::diagnose::free_shapes
