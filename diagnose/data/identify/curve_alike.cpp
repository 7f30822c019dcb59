// SPDX-License-Identifier: MIT
#include "curve_alike.h"

#include <Eigen/Dense>
#include <algorithm>

#include "calibration_reach.h"
#include "criteria.h"
#include "hats.h"

namespace flange::diagnose {
namespace {

// The values at the knots of the least-squares curve of x through `curve` (a light ridge keeps
// knots no sample reaches at 0).
Eigen::VectorXd curve_of(const free_shapes::Hats& hats, const std::vector<double>& x,
                         const std::vector<double>& curve) {
  const auto count = static_cast<Eigen::Index>(hats.knots.size());
  Eigen::MatrixXd normal = Eigen::MatrixXd::Identity(count, count) * 1e-9;
  Eigen::VectorXd right = Eigen::VectorXd::Zero(count);
  for (std::size_t i = 0; i < x.size(); ++i) {
    const auto [first, last] = hats.support(x[i]);
    for (std::size_t a = first; a <= last; ++a) {
      const double wa = hats.weight(a, x[i]);
      right(static_cast<Eigen::Index>(a)) += wa * curve[i];
      for (std::size_t b = first; b <= last; ++b) {
        normal(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b)) +=
            wa * hats.weight(b, x[i]);
      }
    }
  }
  return normal.ldlt().solve(right);
}

std::vector<double> evaluate(const free_shapes::Hats& hats, const Eigen::VectorXd& values,
                             const std::vector<double>& x) {
  std::vector<double> out(x.size(), 0.0);
  for (std::size_t i = 0; i < x.size(); ++i) {
    const auto [first, last] = hats.support(x[i]);
    for (std::size_t k = first; k <= last; ++k) {
      out[i] += hats.weight(k, x[i]) * values(static_cast<Eigen::Index>(k));
    }
  }
  return out;
}

double mean_square_apart(const std::vector<double>& a, const std::vector<double>& b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) sum += (a[i] - b[i]) * (a[i] - b[i]);
  return a.empty() ? 0.0 : sum / static_cast<double>(a.size());
}

}  // namespace

std::optional<std::vector<double>> curve_of_one_variable_alike(
    const std::vector<double>& cal_x, const std::vector<double>& cal_curve,
    const std::vector<double>& ho_x, const std::vector<double>& ho_curve,
    const std::vector<double>& ho_left, double noise_v, int knots) {
  if (cal_x.size() < 2 || cal_x.size() != cal_curve.size() || ho_x.size() != ho_curve.size() ||
      ho_left.size() != ho_x.size() || knots < 2) {
    return std::nullopt;
  }
  const auto [lowest, highest] = std::minmax_element(cal_x.begin(), cal_x.end());
  if (!(*highest > *lowest)) return std::nullopt;
  const free_shapes::Hats hats =
      free_shapes::hats_between(*lowest, *highest, static_cast<std::size_t>(knots));
  const Eigen::VectorXd values = curve_of(hats, cal_x, cal_curve);
  std::vector<double> on_cal = evaluate(hats, values, cal_x);
  const double margin = criteria::kConfoundingMargin * noise_v * noise_v;
  // On the held-out part the curve of x must leave at most the margin more than the pick leaves
  // (the gap before the pick is what it leaves plus what it adds).
  const std::vector<double> on_ho = evaluate(hats, values, ho_x);
  std::vector<double> before(ho_left.size());
  for (std::size_t i = 0; i < before.size(); ++i) before[i] = ho_left[i] + ho_curve[i];
  const std::vector<double> none(ho_left.size(), 0.0);
  const double more_left = mean_square_apart(before, on_ho) - mean_square_apart(ho_left, none);
  if (mean_square_apart(on_cal, cal_curve) > margin || more_left > margin) return std::nullopt;
  return on_cal;
}

std::vector<std::size_t> name_classes_alike(const Parts& parts, Selection& selection,
                                            std::string FreeShapeFamily::*other_of,
                                            const std::vector<double>& heldout_x,
                                            const CurveIsAlike& is_alike) {
  const std::vector<std::size_t> within =
      calibration_reach(parts.calibration, parts.heldout).heldout_within;
  std::vector<std::size_t> named;
  for (std::size_t k = 0; k < selection.picks.size(); ++k) {
    Pick& pick = selection.picks[k];
    if (pick.step.candidates.empty() || !pick.chosen().free_shape) continue;
    const FreeShapeFit& shape = *pick.chosen().free_shape;
    const std::string& other = shape.family.*other_of;
    std::vector<std::string>& alike = pick.finding.indistinguishable_from;
    if (other.empty() || other == pick.finding.name ||
        std::find(alike.begin(), alike.end(), other) != alike.end()) {
      continue;
    }
    HeldoutCurve heldout;
    for (const std::size_t i : within) {
      heldout.x.push_back(heldout_x[i]);
      heldout.curve.push_back(shape.heldout_voltage_v[i]);
      heldout.left.push_back(pick.chosen().heldout_error[i]);
    }
    if (is_alike(shape, heldout)) {
      alike.push_back(other);
      named.push_back(k);
    }
  }
  return named;
}

}  // namespace flange::diagnose
