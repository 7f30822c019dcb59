// SPDX-License-Identifier: MIT
#include "parameter_profile.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "criteria.h"

namespace flange::diagnose {
namespace {

constexpr int kRefitSteps = 4;       // Gauss-Newton steps of a refit (it stops when one gains none)
constexpr int kMostDoublings = 12;   // an end found within 4096 first steps, or the edge taken
constexpr int kHalvings = 6;         // an end placed within a 64th of its bracket

double value_of(const std::vector<sim::EffectSettings>& modelled, const ModelledValue& v) {
  return modelled[v.effect].params.at(v.range.key);
}

void set_value(std::vector<sim::EffectSettings>& modelled, const ModelledValue& v, double x) {
  modelled[v.effect].params[v.range.key] = std::clamp(x, v.range.lo, v.range.hi);
}

Eigen::VectorXd as_vector(const std::vector<double>& v) {
  return Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(v.size()));
}

// Value k moved, the others refitted towards the fitted voltage.
class Refit {
 public:
  struct Point {
    std::vector<sim::EffectSettings> modelled;
    Eigen::VectorXd left;  // the fitted voltage less this point's
    double rms_v() const { return left.norm() / std::sqrt(std::max(1.0, static_cast<double>(left.size()))); }
  };

  Refit(const TwinReplay& replay, const std::vector<sim::EffectSettings>& modelled,
        const std::vector<ModelledValue>& values, const Eigen::MatrixXd& columns, std::size_t k)
      : replay_(replay), modelled_(modelled), values_(values), k_(k) {
    fitted_v_ = as_vector(replay.voltage(modelled));
    for (std::size_t j = 0; j < values.size(); ++j) {
      if (j != k) others_.push_back(j);
    }
    const auto o = static_cast<Eigen::Index>(others_.size());
    // Columns scaled to unit norm, so that the rank decisions do not depend on the values' units.
    scale_ = Eigen::VectorXd::Ones(o);
    Eigen::MatrixXd unit(columns.rows(), o);
    for (Eigen::Index a = 0; a < o; ++a) {
      const Eigen::VectorXd c = columns.col(static_cast<Eigen::Index>(others_[a]));
      if (c.norm() > 0.0) scale_(a) = c.norm();
      unit.col(a) = c / scale_(a);
    }
    compensation_ = Eigen::VectorXd::Zero(o);
    if (o == 0) return;  // a value alone: nothing compensates (and no decomposition of nothing)
    solver_.setThreshold(1e-9);
    solver_.compute(unit);
    compensation_ = solve(columns.col(static_cast<Eigen::Index>(k)));
  }

  Point at(double x) const {
    Point best{modelled_, {}};
    const double dx = x - value_of(modelled_, values_[k_]);
    set_value(best.modelled, values_[k_], x);
    for (std::size_t a = 0; a < others_.size(); ++a) {
      const ModelledValue& v = values_[others_[a]];
      set_value(best.modelled, v, value_of(modelled_, v) - compensation_(static_cast<Eigen::Index>(a)) * dx);
    }
    best.left = left_by(best.modelled);
    for (int step = 0; step < kRefitSteps && !others_.empty(); ++step) {
      Point next{best.modelled, {}};
      const Eigen::VectorXd move = solve(best.left);
      for (std::size_t a = 0; a < others_.size(); ++a) {
        const ModelledValue& v = values_[others_[a]];
        set_value(next.modelled, v, value_of(best.modelled, v) + move(static_cast<Eigen::Index>(a)));
      }
      next.left = left_by(next.modelled);
      if (next.left.norm() >= best.left.norm()) break;
      best = std::move(next);
    }
    return best;
  }

 private:
  Eigen::VectorXd left_by(const std::vector<sim::EffectSettings>& modelled) const {
    return fitted_v_ - as_vector(replay_.voltage(modelled));
  }
  // The least-squares move of the other values that takes `target` from the voltage.
  Eigen::VectorXd solve(const Eigen::VectorXd& target) const {
    return solver_.solve(target).cwiseQuotient(scale_);
  }

  const TwinReplay& replay_;
  const std::vector<sim::EffectSettings>& modelled_;
  const std::vector<ModelledValue>& values_;
  std::size_t k_;
  std::vector<std::size_t> others_;
  Eigen::VectorXd fitted_v_, scale_, compensation_;
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> solver_;
};

// The end on one side (`direction` +1 or -1) of the values the data allow.
ProfileEnd profile_end(const Refit& refit, const std::vector<sim::EffectSettings>& modelled,
                       const ModelledValue& v, double direction, double first_step,
                       double limit_v) {
  const double at = value_of(modelled, v);
  const double edge = direction > 0 ? v.range.hi : v.range.lo;
  const auto is_edge = [&](double x) { return direction > 0 ? x >= edge : x <= edge; };
  ProfileEnd within{at, modelled, is_edge(at)};
  if (within.at_edge) return within;
  double step = std::isfinite(first_step) && first_step > 0.0 ? first_step : std::abs(edge - at);
  double beyond = std::numeric_limits<double>::quiet_NaN();
  for (int d = 0; d < kMostDoublings && std::isnan(beyond); ++d, step *= 2.0) {
    const double x = std::clamp(at + direction * step, v.range.lo, v.range.hi);
    Refit::Point point = refit.at(x);
    if (point.rms_v() > limit_v) {
      beyond = x;
    } else {
      within = {x, std::move(point.modelled), is_edge(x)};
      if (within.at_edge) return within;
    }
  }
  if (std::isnan(beyond)) return within;
  for (int h = 0; h < kHalvings; ++h) {
    const double x = 0.5 * (within.value + beyond);
    Refit::Point point = refit.at(x);
    if (point.rms_v() > limit_v) {
      beyond = x;
    } else {
      within = {x, std::move(point.modelled), false};
    }
  }
  return within;
}

Eigen::VectorXd derivative(const TwinReplay& replay,
                           const std::vector<sim::EffectSettings>& modelled,
                           const ModelledValue& value) {
  const double at = value_of(modelled, value);
  const double h = 1e-4 * (value.range.hi - value.range.lo);
  const double up = std::min(at + h, value.range.hi), down = std::max(at - h, value.range.lo);
  std::vector<sim::EffectSettings> moved = modelled;
  moved[value.effect].params[value.range.key] = up;
  const Eigen::VectorXd v_up = as_vector(replay.voltage(moved));
  moved[value.effect].params[value.range.key] = down;
  return (v_up - as_vector(replay.voltage(moved))) / (up - down);
}

}  // namespace

Eigen::MatrixXd value_columns(const TwinReplay& replay,
                              const std::vector<sim::EffectSettings>& modelled,
                              const std::vector<ModelledValue>& values) {
  Eigen::MatrixXd columns(static_cast<Eigen::Index>(replay.size()),
                          static_cast<Eigen::Index>(values.size()));
  for (std::size_t k = 0; k < values.size(); ++k) {
    columns.col(static_cast<Eigen::Index>(k)) = derivative(replay, modelled, values[k]);
  }
  return columns;
}

ValueProfile profile_value(const TwinReplay& replay,
                           const std::vector<sim::EffectSettings>& modelled,
                           const std::vector<ModelledValue>& values,
                           const Eigen::MatrixXd& columns, std::size_t k, double resolution,
                           double noise_v) {
  const Refit refit(replay, modelled, values, columns, k);
  const double limit_v = std::sqrt(criteria::kScoreResolution) * noise_v;
  return {profile_end(refit, modelled, values[k], -1.0, resolution, limit_v),
          profile_end(refit, modelled, values[k], +1.0, resolution, limit_v)};
}

}  // namespace flange::diagnose
