// SPDX-License-Identifier: MIT
#include "table_fit.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "series_statistics.h"

namespace flange::diagnose {
namespace {

// A variable's span held this far open at least, so that a constant one still gets two knots.
constexpr double kLeastSpan = 1.0;
// Where the samples leave a node without data, first differences to its neighbours carry the
// surface on (flat, never beyond what the data hold); weighed this much of a node's mean data, they
// leave the fitted nodes alone.
constexpr double kSmoothnessShare = 1e-4;

std::vector<double> evenly(double lo, double hi, double spacing) {
  if (hi - lo < kLeastSpan) {
    const double mid = 0.5 * (lo + hi);
    lo = mid - 0.5 * kLeastSpan;
    hi = mid + 0.5 * kLeastSpan;
  }
  const int cells = std::max(1, static_cast<int>(std::ceil((hi - lo) / spacing)));
  std::vector<double> knots(static_cast<std::size_t>(cells) + 1);
  for (int k = 0; k <= cells; ++k) knots[static_cast<std::size_t>(k)] = lo + (hi - lo) * k / cells;
  return knots;
}

template <typename Of>
std::pair<double, double> span_over(const std::vector<TabulatedPart>& parts, Of of) {
  double lo = INFINITY, hi = -INFINITY;
  for (const TabulatedPart& part : parts) {
    for (const double x : of(part)) {
      lo = std::min(lo, x);
      hi = std::max(hi, x);
    }
  }
  return {lo, hi};
}

// Each part's ages get knots of their own; knots closer than a thousandth of a day merge.
std::vector<double> age_knots(const std::vector<TabulatedPart>& parts) {
  std::vector<double> knots;
  for (const TabulatedPart& part : parts) {
    const auto [lo, hi] = std::minmax_element(part.age_days.begin(), part.age_days.end());
    const double span = std::max(*hi - *lo, 1e-3);
    for (int k = 0; k < kAgeKnotsPerPart; ++k) {
      knots.push_back(*lo + span * k / (kAgeKnotsPerPart - 1));
    }
  }
  std::sort(knots.begin(), knots.end());
  std::vector<double> merged;
  for (const double k : knots) {
    if (merged.empty() || k - merged.back() > 1e-3) merged.push_back(k);
  }
  if (merged.size() < 2) merged.push_back(merged.back() + 1.0);
  return merged;
}

// The two knots around x (held at the ends) and their weights.
struct Bracket {
  std::size_t lo = 0;
  double upper_weight = 0.0;
};
Bracket bracket(const std::vector<double>& knots, double x) {
  if (x <= knots.front()) return {0, 0.0};
  if (x >= knots.back()) return {knots.size() - 2, 1.0};
  const auto cell =
      static_cast<std::size_t>(std::upper_bound(knots.begin(), knots.end(), x) - knots.begin()) - 1;
  return {cell, (x - knots[cell]) / (knots[cell + 1] - knots[cell])};
}

class TableSystem {
 public:
  TableSystem(const sim::EffectTable& shape, bool with_age)
      : nd_(shape.clearance_mm.size()),
        nt_(shape.temperature_c.size()),
        na_(with_age ? shape.age_days.size() : 0),
        normal_(Eigen::MatrixXd::Zero(size(), size())),
        rhs_(Eigen::VectorXd::Zero(size())) {}

  Eigen::Index size() const { return static_cast<Eigen::Index>(nd_ * nt_ + na_); }
  Eigen::Index node(std::size_t i, std::size_t j) const {
    return static_cast<Eigen::Index>(i * nt_ + j);
  }
  Eigen::Index age_node(std::size_t k) const { return static_cast<Eigen::Index>(nd_ * nt_ + k); }

  // One row of the least squares: weights at nodes, and its target.
  void add_row(const std::vector<std::pair<Eigen::Index, double>>& row, double target) {
    for (const auto& [a, wa] : row) {
      rhs_(a) += wa * target;
      for (const auto& [b, wb] : row) normal_(a, b) += wa * wb;
    }
  }
  void add_difference(Eigen::Index a, Eigen::Index b, double weight) {
    add_row({{a, std::sqrt(weight)}, {b, -std::sqrt(weight)}}, 0.0);
  }
  void add_ridge(Eigen::Index a, double weight) { normal_(a, a) += weight; }
  void add_smoothness(double weight) {
    for (std::size_t i = 0; i < nd_; ++i) {
      for (std::size_t j = 0; j < nt_; ++j) {
        if (i + 1 < nd_) add_difference(node(i, j), node(i + 1, j), weight);
        if (j + 1 < nt_) add_difference(node(i, j), node(i, j + 1), weight);
      }
    }
    for (std::size_t k = 0; k < na_; ++k) {
      if (k + 1 < na_) add_difference(age_node(k), age_node(k + 1), weight);
      add_ridge(age_node(k), 1e-3 * weight);  // the constant belongs to the surface
    }
  }
  // The normal equations of a local basis (each row touches at most six nodes, every node holds
  // a partition of unity) are well conditioned, unlike a polynomial's; with thousands of nodes
  // and up to a million rows, a dense QR of the rows would cost far more.
  Eigen::VectorXd solve() const { return normal_.ldlt().solve(rhs_); }

 private:
  std::size_t nd_, nt_, na_;
  Eigen::MatrixXd normal_;
  Eigen::VectorXd rhs_;
};

std::vector<std::pair<Eigen::Index, double>> row_of(const TableSystem& system,
                                                    const sim::EffectTable& shape, double d,
                                                    double t, const double* age) {
  const Bracket bd = bracket(shape.clearance_mm, d);
  const Bracket bt = bracket(shape.temperature_c, t);
  std::vector<std::pair<Eigen::Index, double>> row = {
      {system.node(bd.lo, bt.lo), (1 - bd.upper_weight) * (1 - bt.upper_weight)},
      {system.node(bd.lo, bt.lo + 1), (1 - bd.upper_weight) * bt.upper_weight},
      {system.node(bd.lo + 1, bt.lo), bd.upper_weight * (1 - bt.upper_weight)},
      {system.node(bd.lo + 1, bt.lo + 1), bd.upper_weight * bt.upper_weight}};
  if (age != nullptr) {
    const Bracket ba = bracket(shape.age_days, *age);
    row.push_back({system.age_node(ba.lo), 1 - ba.upper_weight});
    row.push_back({system.age_node(ba.lo + 1), ba.upper_weight});
  }
  return row;
}

}  // namespace

TableFit fit_effect_table(const std::vector<TabulatedPart>& parts, bool with_age) {
  TableFit fit;
  sim::EffectTable& table = fit.table;
  const auto [d_lo, d_hi] = span_over(
      parts, [](const TabulatedPart& p) -> const std::vector<double>& { return p.clearance_mm; });
  const auto [t_lo, t_hi] = span_over(
      parts, [](const TabulatedPart& p) -> const std::vector<double>& { return p.temperature_c; });
  table.clearance_mm = evenly(d_lo, d_hi, kClearanceKnotSpacingMm);
  table.temperature_c = evenly(t_lo, t_hi, kTemperatureKnotSpacingC);
  if (with_age) table.age_days = age_knots(parts);
  TableSystem system(table, with_age);
  std::size_t rows = 0;
  for (const TabulatedPart& part : parts) {
    for (std::size_t i = 0; i < part.added_v.size(); ++i) {
      system.add_row(row_of(system, table, part.clearance_mm[i], part.temperature_c[i],
                            with_age ? &part.age_days[i] : nullptr),
                     part.added_v[i]);
    }
    rows += part.added_v.size();
  }
  system.add_smoothness(kSmoothnessShare * static_cast<double>(rows) /
                        static_cast<double>(system.size()));
  const Eigen::VectorXd values = system.solve();
  table.added_v.assign(table.clearance_mm.size(), std::vector<double>(table.temperature_c.size()));
  for (std::size_t i = 0; i < table.clearance_mm.size(); ++i) {
    for (std::size_t j = 0; j < table.temperature_c.size(); ++j) {
      table.added_v[i][j] = values(system.node(i, j));
    }
  }
  for (std::size_t k = 0; k < table.age_days.size(); ++k) {
    table.age_added_v.push_back(values(system.age_node(k)));
  }
  for (const TabulatedPart& part : parts) {
    std::vector<double> misfit(part.added_v.size());
    for (std::size_t i = 0; i < misfit.size(); ++i) {
      misfit[i] = table.added_voltage(part.clearance_mm[i], part.temperature_c[i],
                                      with_age ? part.age_days[i] : 0.0) -
                  part.added_v[i];
    }
    fit.misfit_rms_v.push_back(rms_of(misfit));
  }
  return fit;
}

}  // namespace flange::diagnose
