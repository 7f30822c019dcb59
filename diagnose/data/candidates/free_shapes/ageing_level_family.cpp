// SPDX-License-Identifier: MIT
#include "ageing_level_family.h"

#include <fmt/format.h>

#include <algorithm>

#include "calibration_reach.h"
#include "criteria.h"
#include "family_makers.h"
#include "ridge_solve.h"
#include "sensor_age.h"

namespace flange::diagnose::free_shapes {
void AgeingLevelFamily::search(const RecordedPart& calibration, const std::vector<double>&) {
  const std::vector<double> ages = age_days(calibration);
  end_age_days_ = ages.empty() ? 0.0 : *std::max_element(ages.begin(), ages.end());
}

int AgeingLevelFamily::choose_on_heldout(const RecordedPart& calibration,
                                         const std::vector<double>& cal_gap,
                                         const RecordedPart& heldout,
                                         const std::vector<double>& ho_gap, bool no_level_carried,
                                         std::string& how) {
  chosen_.reset();
  const std::vector<double> ho_ages = age_days(heldout);
  const bool heldout_after =
      !ho_ages.empty() && *std::min_element(ho_ages.begin(), ho_ages.end()) > end_age_days_;
  if (!no_level_carried || !heldout_after || ho_gap.empty()) return 0;
  const Eigen::Map<const Eigen::VectorXd> cal(cal_gap.data(),
                                              static_cast<Eigen::Index>(cal_gap.size()));
  Eigen::VectorXd beta = ridge_solve(columns(calibration), cal);
  const Eigen::VectorXd held = columns(heldout) * beta;
  const std::vector<std::size_t> within =
      calibration_reach(calibration.series, heldout.series).heldout_within;
  const bool enough_within = static_cast<double>(within.size()) >=
                             criteria::kLeastShareWithinReach * static_cast<double>(ho_gap.size());
  double sum = 0.0, n = 0.0;
  const auto add = [&](std::size_t i) {
    sum += ho_gap[i] - held(static_cast<Eigen::Index>(i));
    n += 1.0;
  };
  if (enough_within) {
    for (std::size_t i : within) add(i);
  } else {
    for (std::size_t i = 0; i < ho_gap.size(); ++i) add(i);
  }
  const double level = sum / n;
  beta(2) = level;
  chosen_ = beta;
  how = fmt::format("; the level between the sessions, {:.3g} V, chosen on the held-out session",
                    level);
  return 1;
}

std::vector<std::string> AgeingLevelFamily::names() const {
  return {"offset_v", "rate_v_per_day", "level_between_sessions_v"};
}

Eigen::MatrixXd AgeingLevelFamily::columns(const RecordedPart& part) const {
  const std::vector<double> ages = age_days(part);
  Eigen::MatrixXd a = matrix(ages.size(), 3);
  for (std::size_t i = 0; i < ages.size(); ++i) {
    const auto row = static_cast<Eigen::Index>(i);
    a(row, 0) = 1.0;
    a(row, 1) = std::min(ages[i], end_age_days_);
    a(row, 2) = ages[i] > end_age_days_ ? 1.0 : 0.0;
  }
  return a;
}

std::string AgeingLevelFamily::describe(const Eigen::VectorXd& beta) const {
  return fmt::format(
      "a trend in the sensor's age over the calibration session, {:.3g} V + {:.3g} V/day, held "
      "after it, and a level of {:.3g} V between the sessions",
      beta(0), beta(1), beta(2));
}

std::unique_ptr<Family> make_ageing_level(const RecordedPart&) {
  return std::make_unique<AgeingLevelFamily>();
}

}  // namespace flange::diagnose::free_shapes
