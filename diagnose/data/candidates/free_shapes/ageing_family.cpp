// SPDX-License-Identifier: MIT
#include "ageing_family.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "family_makers.h"
#include "grid_search.h"
#include "ridge_solve.h"
#include "sensor_age.h"
#include "series_statistics.h"

namespace flange::diagnose::free_shapes {
namespace {

// How much more of the calibration gap's sum of squares, in its noise variance, a settling or a
// rate the held-out part chooses may leave than the calibration's own best: the 5 % point of a
// chi-square of one value is 3.8, so a settling or rate within 4 sigma^2 is one the calibration
// part cannot reject.
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

AgeingFamily::Profile AgeingFamily::profile(const std::vector<double>& column,
                                            const std::vector<double>& cal_gap) {
  // Centred least squares of the gap on [1, column]: its rate, the sum of squares it leaves and
  // how fast that grows away from the rate (the column's spread), with the offset profiled.
  Profile p{mean_of(column), mean_of(cal_gap), 0.0, 0.0, 0.0};
  double cross = 0.0;
  for (std::size_t i = 0; i < column.size(); ++i) {
    const double c = column[i] - p.mean_column, g = cal_gap[i] - p.mean_gap;
    p.spread += c * c;
    cross += c * g;
    p.least_sse += g * g;
  }
  if (p.spread > 0.0) {
    p.rate = cross / p.spread;
    p.least_sse = std::max(p.least_sse - cross * p.rate, 0.0);
  }
  return p;
}

std::vector<double> AgeingFamily::column_of(const std::vector<double>& ages) const {
  std::vector<double> column(ages.size());
  for (std::size_t i = 0; i < ages.size(); ++i) {
    column[i] = tau_days_ == 0.0 ? ages[i] : std::log1p(ages[i] / tau_days_);
  }
  return column;
}

AgeingFamily::Trial AgeingFamily::heldout_trial(const Profile& p, double cal_bound,
                                                const std::vector<double>& ho_column,
                                                const std::vector<double>& ho_gap) const {
  // The rate the held-out level asks for, kept where the calibration part does not reject it:
  // its sum of squares grows by (rate - p.rate)^2 p.spread away from its own best.
  double sdd = 0.0, srd = 0.0;
  for (std::size_t i = 0; i < ho_column.size(); ++i) {
    const double d = ho_column[i] - p.mean_column;
    sdd += d * d;
    srd += d * (ho_gap[i] - p.mean_gap);
  }
  double rate = sdd > 0.0 ? srd / sdd : p.rate;
  if (p.spread > 0.0) {
    const double reach = std::sqrt(std::max(cal_bound - p.least_sse, 0.0) / p.spread);
    rate = std::clamp(rate, p.rate - reach, p.rate + reach);
  }
  Trial t{tau_days_, rate, p.rate, p.mean_gap - rate * p.mean_column, 0.0};
  for (std::size_t i = 0; i < ho_column.size(); ++i) {
    const double e = ho_gap[i] - t.offset - rate * ho_column[i];
    t.ho_sse += e * e;
  }
  return t;
}

int AgeingFamily::choose_settling(const RecordedPart& calibration,
                                  const std::vector<double>& cal_gap, const RecordedPart& heldout,
                                  const std::vector<double>& ho_gap, std::string& how) {
  const Eigen::Map<const Eigen::VectorXd> cal(cal_gap.data(),
                                              static_cast<Eigen::Index>(cal_gap.size()));
  const Eigen::Map<const Eigen::VectorXd> ho(ho_gap.data(),
                                             static_cast<Eigen::Index>(ho_gap.size()));
  struct SettlingTrial {
    double tau, cal_sse, ho_sse;
  };
  std::vector<SettlingTrial> trials;
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
  const SettlingTrial* best = nullptr;
  for (const SettlingTrial& trial : trials) {
    if (trial.cal_sse > least_cal + kSettlingLeeway * variance) continue;
    if (!best || trial.ho_sse < best->ho_sse ||
        (trial.ho_sse == best->ho_sse && trial.tau == chosen_)) {
      best = &trial;
    }
  }
  tau_days_ = best->tau;
  how = curvature_note();
  chosen_ = tau_days_;
  return 1;
}

int AgeingFamily::choose_on_heldout(const RecordedPart& calibration,
                                    const std::vector<double>& cal_gap, const RecordedPart& heldout,
                                    const std::vector<double>& ho_gap, bool no_level_carried,
                                    std::string& how) {
  heldout_level_.reset();
  if (!no_level_carried) return choose_settling(calibration, cal_gap, heldout, ho_gap, how);
  const std::vector<double> cal_ages = age_days(calibration), ho_ages = age_days(heldout);
  const std::vector<double> searched = taus();
  std::vector<Profile> profiles;
  double least_cal = std::numeric_limits<double>::infinity();
  for (double tau : searched) {
    tau_days_ = tau;
    profiles.push_back(profile(column_of(cal_ages), cal_gap));
    least_cal = std::min(least_cal, profiles.back().least_sse);
  }
  const double variance =
      least_cal / static_cast<double>(std::max<std::size_t>(cal_gap.size(), 4) - 3);
  const double cal_bound = least_cal + kSettlingLeeway * variance;
  std::optional<Trial> best;
  for (std::size_t k = 0; k < searched.size(); ++k) {
    tau_days_ = searched[k];
    if (profiles[k].least_sse > cal_bound) continue;
    const Trial trial = heldout_trial(profiles[k], cal_bound, column_of(ho_ages), ho_gap);
    if (!best || trial.ho_sse < best->ho_sse ||
        (trial.ho_sse == best->ho_sse && trial.tau == chosen_)) {
      best = trial;
    }
  }
  tau_days_ = best->tau;
  heldout_level_ = Eigen::Vector2d(best->offset, best->rate);
  const bool rate_moved = best->rate != best->calibration_rate;
  how = curvature_note();
  if (rate_moved) {
    how += fmt::format(
        "; its {} the calibration session leaves open, chosen on the held-out session's level "
        "({:.3g} where the calibration part alone took {:.3g})",
        tau_days_ == 0.0 ? "rate (V/day), which" : "size (V), which", best->rate,
        best->calibration_rate);
  }
  chosen_ = tau_days_;
  return rate_moved ? 2 : 1;
}

std::optional<Eigen::VectorXd> AgeingFamily::values_chosen_on_heldout() const {
  if (!heldout_level_) return std::nullopt;
  return Eigen::VectorXd(*heldout_level_);
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

std::string AgeingFamily::curvature_note() const {
  if (tau_days_ == chosen_) return "";
  return fmt::format(
      "; its curvature, which the calibration session leaves open, chosen on the held-out "
      "session's level ({} where the calibration part alone took {})",
      describe_tau(tau_days_), describe_tau(chosen_));
}

std::string AgeingFamily::describe_tau(double tau_days) {
  return tau_days == 0.0 ? "a straight line" : fmt::format("a settling over {:.3g} d", tau_days);
}

std::unique_ptr<Family> make_continuing_ageing(const RecordedPart&) {
  return std::make_unique<AgeingFamily>();
}

}  // namespace flange::diagnose::free_shapes
