// SPDX-License-Identifier: MIT
#include "ripple_family.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "family_makers.h"
#include "grid_search.h"
#include "ridge_solve.h"

namespace flange::diagnose::free_shapes {

void RippleFamily::search(const RecordedPart& calibration, const std::vector<double>& gap_v) {
  const std::vector<double>& d = calibration.series.clearance_mm;
  const auto [lo, hi] = std::minmax_element(d.begin(), d.end());
  const double range = *hi - *lo;
  if (range <= 2.0 * kShortestRippleMm) return;
  const auto sse = [&](double per_mm) { return fitted_sse(d, gap_v, per_mm); };
  const double first = 2.0 / range, last = 1.0 / kShortestRippleMm, step = 0.25 / range;
  SearchPoint lattice_best{{first}};
  search_points_at_once(
      lattice({stepped_axis(first, last, step)}),
      [&](const std::vector<double>& at) { return sse(at[0]); }, lattice_best);
  const double best = lattice_best.at[0];
  // Golden section within a lattice step either side of the best.
  double a = std::max(first, best - step), b = std::min(last, best + step);
  const double golden = 0.5 * (std::sqrt(5.0) - 1.0);
  double x1 = b - golden * (b - a), x2 = a + golden * (b - a);
  double f1 = sse(x1), f2 = sse(x2);
  for (int i = 0; i < 40; ++i) {
    if (f1 < f2) {
      b = x2, x2 = x1, f2 = f1, x1 = b - golden * (b - a), f1 = sse(x1);
    } else {
      a = x1, x1 = x2, f1 = f2, x2 = a + golden * (b - a), f2 = sse(x2);
    }
  }
  per_mm_ = 0.5 * (a + b);
  first_per_mm_ = first, last_per_mm_ = last, step_per_mm_ = step;
}

std::map<std::string, std::string> RippleFamily::search_edges() const {
  // Golden section ends within a thousandth of a lattice step of an edge it is pressed against.
  const double near = 1e-3 * step_per_mm_;
  if (per_mm_ <= 0.0) return {};
  if (per_mm_ <= first_per_mm_ + near) {
    return {{"ripple_period_mm", fmt::format(">= {:.3g}", 1.0 / per_mm_)}};
  }
  if (per_mm_ >= last_per_mm_ - near) {
    return {{"ripple_period_mm", fmt::format("<= {:.3g}", 1.0 / per_mm_)}};
  }
  return {};
}

std::vector<std::string> RippleFamily::names() const {
  std::vector<std::string> names;
  for (int k = 0; k < kRippleKnots; ++k) names.push_back(fmt::format("ripple_v_at_phase_{}", k));
  return names;
}

Eigen::MatrixXd RippleFamily::columns(const RecordedPart& part) const {
  const std::vector<double>& d = part.series.clearance_mm;
  Eigen::MatrixXd a = matrix(d.size(), kRippleKnots);
  for (std::size_t i = 0; i < d.size(); ++i) {
    const auto [k, w] = place(d[i], per_mm_);
    a(static_cast<Eigen::Index>(i), k) = 1.0 - w;
    a(static_cast<Eigen::Index>(i), (k + 1) % kRippleKnots) = w;
  }
  return a;
}

void RippleFamily::summarise(const Eigen::VectorXd&, const RecordedPart&,
                             std::map<std::string, double>& params) const {
  if (per_mm_ > 0.0) params["ripple_period_mm"] = 1.0 / per_mm_;
}

std::string RippleFamily::describe(const Eigen::VectorXd& beta) const {
  return fmt::format(
      "a ripple in the clearance: period {:.3g} mm, {:.3g} V peak to peak (a curve over one "
      "period, repeated beyond the calibration's range)",
      per_mm_ > 0.0 ? 1.0 / per_mm_ : 0.0, beta.maxCoeff() - beta.minCoeff());
}

std::pair<Eigen::Index, double> RippleFamily::place(double d, double per_mm) {
  const double u = d * per_mm * kRippleKnots;
  const double k = std::floor(u);
  const auto index = static_cast<long long>(k) % kRippleKnots;
  return {static_cast<Eigen::Index>(index < 0 ? index + kRippleKnots : index), u - k};
}

// From the 8 x 8 normal equations summed row by row (each row touches two hats).
double RippleFamily::fitted_sse(const std::vector<double>& d, const std::vector<double>& gap,
                                double per_mm) {
  Eigen::Matrix<double, kRippleKnots, kRippleKnots> normal =
      Eigen::Matrix<double, kRippleKnots, kRippleKnots>::Zero();
  Eigen::Matrix<double, kRippleKnots, 1> rhs = Eigen::Matrix<double, kRippleKnots, 1>::Zero();
  double yy = 0.0;
  for (std::size_t i = 0; i < d.size(); ++i) {
    const auto [k, w] = place(d[i], per_mm);
    const Eigen::Index k1 = (k + 1) % kRippleKnots;
    normal(k, k) += (1.0 - w) * (1.0 - w);
    normal(k1, k1) += w * w;
    normal(k, k1) += (1.0 - w) * w;
    normal(k1, k) += (1.0 - w) * w;
    rhs(k) += (1.0 - w) * gap[i];
    rhs(k1) += w * gap[i];
    yy += gap[i] * gap[i];
  }
  normal.diagonal().array() += kRidge * normal.diagonal().maxCoeff();
  const Eigen::Matrix<double, kRippleKnots, 1> beta = normal.ldlt().solve(rhs);
  return yy - beta.dot(rhs);
}

std::unique_ptr<Family> make_clearance_ripple(const RecordedPart&) {
  return std::make_unique<RippleFamily>();
}

}  // namespace flange::diagnose::free_shapes
