// SPDX-License-Identifier: MIT
#include "ageing_family.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "family_makers.h"
#include "grid_search.h"
#include "ridge_solve.h"
#include "sensor_age.h"

namespace flange::diagnose::free_shapes {
namespace {

// How much more of the calibration gap's sum of squares, in its noise variance, a settling the
// held-out part chooses may leave than the calibration's own best: the 5 % point of a chi-square
// of one value is 3.8, so a settling within 4 sigma^2 is one the calibration part cannot reject.
constexpr double kSettlingLeeway = 4.0;

}  // namespace

std::vector<double> AgeingFamily::taus() {
  std::vector<double> taus = {0.0};
  for (double tau = 0.002; tau <= 10.0; tau *= 1.5) taus.push_back(tau);
  return taus;
}

void AgeingFamily::search(const RecordedPart& calibration, const std::vector<double>& gap_v) {
  const Eigen::Map<const Eigen::VectorXd> gap(gap_v.data(),
                                              static_cast<Eigen::Index>(gap_v.size()));
  SearchPoint best{{chosen_}};
  search_points(
      lattice({taus()}),
      [&](const std::vector<double>& at) {
        tau_days_ = at[0];
        const Eigen::MatrixXd a = columns(calibration);
        const Eigen::VectorXd beta = a.colPivHouseholderQr().solve(gap);
        return (gap - a * beta).squaredNorm();
      },
      best);
  chosen_ = best.at[0];
  tau_days_ = chosen_;
}

std::map<std::string, std::string> AgeingFamily::search_edges() const {
  const std::vector<double> searched = taus();
  if (tau_days_ == searched.back()) {
    return {{"settling_tau_days", fmt::format(">= {:.3g}", tau_days_)}};
  }
  if (tau_days_ == searched[1]) return {{"settling_tau_days", fmt::format("<= {:.3g}", tau_days_)}};
  return {};
}

int AgeingFamily::choose_on_heldout(const RecordedPart& calibration,
                                    const std::vector<double>& cal_gap, const RecordedPart& heldout,
                                    const std::vector<double>& ho_gap, std::string& how) {
  const Eigen::Map<const Eigen::VectorXd> cal(cal_gap.data(),
                                              static_cast<Eigen::Index>(cal_gap.size()));
  const Eigen::Map<const Eigen::VectorXd> ho(ho_gap.data(),
                                             static_cast<Eigen::Index>(ho_gap.size()));
  struct Trial {
    double tau, cal_sse, ho_sse;
  };
  std::vector<Trial> trials;
  double least_cal = std::numeric_limits<double>::infinity();
  for (double tau : taus()) {
    tau_days_ = tau;
    const Eigen::MatrixXd a = columns(calibration);
    const Eigen::VectorXd beta = ridge_solve(a, cal);
    trials.push_back(
        {tau, (cal - a * beta).squaredNorm(), (ho - columns(heldout) * beta).squaredNorm()});
    least_cal = std::min(least_cal, trials.back().cal_sse);
  }
  const double variance =
      least_cal / static_cast<double>(std::max<Eigen::Index>(cal.size() - 3, 1));
  const Trial* best = nullptr;
  for (const Trial& trial : trials) {
    if (trial.cal_sse > least_cal + kSettlingLeeway * variance) continue;
    if (!best || trial.ho_sse < best->ho_sse ||
        (trial.ho_sse == best->ho_sse && trial.tau == chosen_)) {
      best = &trial;
    }
  }
  tau_days_ = best->tau;
  if (tau_days_ != chosen_) {
    how = fmt::format(
        "; its curvature, which the calibration session leaves open, chosen on the held-out "
        "session's level ({} where the calibration part alone took {})",
        describe_tau(tau_days_), describe_tau(chosen_));
  }
  chosen_ = tau_days_;
  return 1;
}

std::vector<std::string> AgeingFamily::names() const {
  return {"offset_v", tau_days_ == 0.0 ? "rate_v_per_day" : "settling_v"};
}

Eigen::MatrixXd AgeingFamily::columns(const RecordedPart& part) const {
  const std::vector<double> ages = age_days(part);
  Eigen::MatrixXd a = matrix(ages.size(), 2);
  for (std::size_t i = 0; i < ages.size(); ++i) {
    const auto row = static_cast<Eigen::Index>(i);
    a(row, 0) = 1.0;
    a(row, 1) = tau_days_ == 0.0 ? ages[i] : std::log1p(ages[i] / tau_days_);
  }
  return a;
}

void AgeingFamily::summarise(const Eigen::VectorXd&, const RecordedPart&,
                             std::map<std::string, double>& params) const {
  if (tau_days_ > 0.0) params["settling_tau_days"] = tau_days_;
}

std::string AgeingFamily::describe(const Eigen::VectorXd& beta) const {
  if (tau_days_ == 0.0) {
    return fmt::format("a trend in the sensor's age: {:.3g} V + {:.3g} V/day", beta(0), beta(1));
  }
  return fmt::format("a settling in the sensor's age: {:.3g} V + {:.3g} V ln(1 + age / {:.3g} d)",
                     beta(0), beta(1), tau_days_);
}

std::string AgeingFamily::describe_tau(double tau_days) {
  return tau_days == 0.0 ? "a straight line" : fmt::format("a settling over {:.3g} d", tau_days);
}

std::unique_ptr<Family> make_continuing_ageing(const RecordedPart&) {
  return std::make_unique<AgeingFamily>();
}

}  // namespace flange::diagnose::free_shapes
