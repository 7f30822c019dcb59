// SPDX-License-Identifier: MIT
#include "regression.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "input_error.h"

namespace flange::host {

std::vector<std::pair<int, int>> regression_terms(int order) {
  // Orders are nested: walking p upwards and appending only new terms makes the terms of each
  // order a prefix of the next.
  std::vector<std::pair<int, int>> terms;
  for (int p = 0; p <= order; ++p) {
    const int t_limit = p == 0 ? 0 : std::max(1, p - 1);
    for (int i = 0; i <= p; ++i) {
      for (int j = 0; j <= t_limit && i + j <= p; ++j) {
        if (std::find(terms.begin(), terms.end(), std::make_pair(i, j)) == terms.end()) {
          terms.emplace_back(i, j);
        }
      }
    }
  }
  return terms;
}

namespace {

double monomial(double v, double t, const std::pair<int, int>& term) {
  double value = 1.0;
  for (int k = 0; k < term.first; ++k) value *= v;
  for (int k = 0; k < term.second; ++k) value *= t;
  return value;
}

// Cross-validation folds are interleaved blocks of consecutive rows: block b belongs to fold
// b mod k. A held-out row's close neighbours in time are mostly in its own block, and every fold
// spans the whole recording, so a regime that occurs only once (a heating cycle) is in every
// training set.
constexpr std::size_t kFoldBlockRows = 64;

int fold_of(std::size_t row, int folds) {
  return static_cast<int>((row / kFoldBlockRows) % static_cast<std::size_t>(folds));
}

// Rows of `fold` (or all rows for fold < 0) as a design matrix and target vector.
void fold_design(const CalibrationData& data, int fold, int folds, const VariableScaling& s,
                 const std::vector<std::pair<int, int>>& terms, Eigen::MatrixXd& x,
                 Eigen::VectorXd& y) {
  std::vector<std::size_t> rows;
  for (std::size_t row = 0; row < data.clearance_mm.size(); ++row) {
    if (fold < 0 || fold_of(row, folds) == fold) rows.push_back(row);
  }
  x.resize(static_cast<Eigen::Index>(rows.size()), static_cast<Eigen::Index>(terms.size()));
  y.resize(static_cast<Eigen::Index>(rows.size()));
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const double v = (data.voltage_v[rows[i]] - s.v_center) / s.v_half;
    const double t = (data.temp_c[rows[i]] - s.t_center) / s.t_half;
    for (std::size_t k = 0; k < terms.size(); ++k) {
      x(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k)) = monomial(v, t, terms[k]);
    }
    y(static_cast<Eigen::Index>(i)) = data.clearance_mm[rows[i]];
  }
}

// The triangular factor of one block of rows: R (p x p) and Q^T y (p), enough to fit any
// prefix of the terms, alone or stacked with other blocks.
struct BlockFactor {
  Eigen::MatrixXd r;
  Eigen::VectorXd qty;
};

BlockFactor factor(const Eigen::MatrixXd& x, const Eigen::VectorXd& y) {
  const Eigen::Index p = x.cols();
  if (x.rows() == 0) return {Eigen::MatrixXd::Zero(0, p), Eigen::VectorXd::Zero(0)};
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(x);
  const Eigen::Index k = std::min(x.rows(), p);
  BlockFactor f;
  f.r = qr.matrixQR().topRows(k).triangularView<Eigen::Upper>();
  f.qty = (qr.householderQ().transpose() * y).head(k);
  return f;
}

BlockFactor stack(const std::vector<const BlockFactor*>& blocks, Eigen::Index p) {
  Eigen::Index rows = 0;
  for (const BlockFactor* b : blocks) rows += b->r.rows();
  Eigen::MatrixXd x(rows, p);
  Eigen::VectorXd y(rows);
  Eigen::Index at = 0;
  for (const BlockFactor* b : blocks) {
    x.middleRows(at, b->r.rows()) = b->r;
    y.segment(at, b->r.rows()) = b->qty;
    at += b->r.rows();
  }
  return factor(x, y);
}

// Least-squares coefficients of the first `p` terms from a factor of all terms: the leading
// p x p block of R belongs to the prefix of the columns.
Eigen::VectorXd solve_prefix(const BlockFactor& f, Eigen::Index p) {
  return f.r.topLeftCorner(p, p).triangularView<Eigen::Upper>().solve(f.qty.head(p));
}

struct Errors {
  double sse = 0.0, sae = 0.0;
  std::size_t n = 0;
};

// Errors of `coefficients` on the rows of `fold` (all rows for fold < 0).
Errors errors_of(const CalibrationData& data, int fold, int folds, const VariableScaling& s,
                 const std::vector<std::pair<int, int>>& terms,
                 const Eigen::VectorXd& coefficients) {
  Errors e;
  for (std::size_t row = 0; row < data.clearance_mm.size(); ++row) {
    if (fold >= 0 && fold_of(row, folds) != fold) continue;
    const double v = (data.voltage_v[row] - s.v_center) / s.v_half;
    const double t = (data.temp_c[row] - s.t_center) / s.t_half;
    double predicted = 0.0;
    for (std::size_t k = 0; k < terms.size(); ++k) {
      predicted += coefficients(static_cast<Eigen::Index>(k)) * monomial(v, t, terms[k]);
    }
    const double residual = data.clearance_mm[row] - predicted;
    e.sse += residual * residual;
    e.sae += std::abs(residual);
    ++e.n;
  }
  return e;
}

// Every fold needs rows of its own: the folds take blocks of kFoldBlockRows in turn.
void require_rows_for_folds(std::size_t n, int folds) {
  const std::size_t min_rows = std::max<std::size_t>(
      {regression_terms(kMinRegressionOrder).size() * 2 + 2, static_cast<std::size_t>(folds) * 4,
       static_cast<std::size_t>(folds - 1) * kFoldBlockRows + 1});
  if (n < min_rows) {
    throw InputError(fmt::format(
        "calibration data: {} points with a clearance reference; at least {} are needed for "
        "{}-fold cross-validation (in blocks of {} rows) of even the first order",
        n, min_rows, folds, kFoldBlockRows));
  }
}

void require_spread(const std::vector<double>& values, const char* column) {
  const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  if (*hi - *lo <= 1e-9 * std::max(1.0, std::abs(*hi))) {
    throw InputError(fmt::format(
        "calibration data: column {} is constant ({}); the regression needs measurements over "
        "a range of {}",
        column, *lo, std::string(column) == "temp_c" ? "temperatures" : "clearances"));
  }
}

// Voltage and temperature that move together leave the fit free to trade one for the other:
// exactly collinear data is caught by the rank test below, nearly collinear data (a temperature
// that follows the voltage to within millikelvin) passes it and gives wild coefficients. The
// share of the temperature's spread that the voltage does not explain, sqrt(1 - rho^2), must be
// at least 1 %.
void require_independent(const std::vector<double>& v, const std::vector<double>& t) {
  constexpr double kMinIndependentShare = 0.01;
  const double n = static_cast<double>(v.size());
  double mv = 0, mt = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    mv += v[i] / n;
    mt += t[i] / n;
  }
  double svv = 0, stt = 0, svt = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    svv += (v[i] - mv) * (v[i] - mv);
    stt += (t[i] - mt) * (t[i] - mt);
    svt += (v[i] - mv) * (t[i] - mt);
  }
  const double rho = svt / std::sqrt(svv * stt);
  const double independent = std::sqrt(std::max(0.0, 1.0 - rho * rho));
  if (independent < kMinIndependentShare) {
    throw InputError(fmt::format(
        "calibration data: voltage_v and temp_c move together (correlation {:.6f}; only {:.3g} % "
        "of the temperature's spread is independent of the voltage, at least {} % is needed), so "
        "their effects cannot be told apart; measure over independent ranges of both",
        rho, 100.0 * independent, 100.0 * kMinIndependentShare));
  }
}

// Enough rows for cross-validation, a spread in every column, and voltage and temperature that
// do not move together.
void require_fittable(const CalibrationData& data, int folds) {
  const std::size_t n = data.clearance_mm.size();
  // A spread needs two points; what is wrong with the values says more than their count.
  if (n < 2) require_rows_for_folds(n, folds);
  require_spread(data.voltage_v, "voltage_v");
  require_spread(data.temp_c, "temp_c");
  require_spread(data.clearance_mm, "clearance_mm");
  require_independent(data.voltage_v, data.temp_c);
  require_rows_for_folds(n, folds);
}

// The fit runs on voltage and temperature scaled to [-1, 1] over the data's range.
VariableScaling scaling_of(const CalibrationData& data) {
  VariableScaling s;
  const auto [v_lo, v_hi] = std::minmax_element(data.voltage_v.begin(), data.voltage_v.end());
  const auto [t_lo, t_hi] = std::minmax_element(data.temp_c.begin(), data.temp_c.end());
  s.v_center = (*v_lo + *v_hi) / 2.0;
  s.v_half = (*v_hi - *v_lo) / 2.0;
  s.t_center = (*t_lo + *t_hi) / 2.0;
  s.t_half = (*t_hi - *t_lo) / 2.0;
  return s;
}

double total_sum_of_squares(const std::vector<double>& values) {
  double mean = 0.0;
  for (double d : values) mean += d;
  mean /= static_cast<double>(values.size());
  double sst = 0.0;
  for (double d : values) sst += (d - mean) * (d - mean);
  return sst;
}

// What the fit of every order shares: the data and its scaling, one factor per fold over all
// terms up to the highest order, the whole as their stack, and the total sum of squares.
struct FitContext {
  FitContext(const CalibrationData& data, const RegressionOptions& options);

  const CalibrationData& data;
  int folds = 0;
  VariableScaling s;
  std::vector<BlockFactor> fold_factors;
  BlockFactor whole;
  Eigen::Index p_all = 0;
  double sst = 0.0;
};

FitContext::FitContext(const CalibrationData& data_in, const RegressionOptions& options)
    : data(data_in), folds(options.folds), s(scaling_of(data_in)) {
  const std::vector<std::pair<int, int>> all_terms = regression_terms(options.max_order);
  p_all = static_cast<Eigen::Index>(all_terms.size());
  for (int f = 0; f < folds; ++f) {
    Eigen::MatrixXd x;
    Eigen::VectorXd y;
    fold_design(data, f, folds, s, all_terms, x, y);
    fold_factors.push_back(factor(x, y));
  }
  std::vector<const BlockFactor*> every;
  for (const BlockFactor& f : fold_factors) every.push_back(&f);
  whole = stack(every, p_all);
  sst = total_sum_of_squares(data.clearance_mm);
}

Eigen::VectorXd diagonal_magnitudes(const BlockFactor& f, Eigen::Index p) {
  return f.r.topLeftCorner(p, p).diagonal().cwiseAbs();
}

// Rank: a diagonal of R that is tiny next to the largest means a column is a combination of
// the others on this data.
bool rank_deficient(const Eigen::VectorXd& diagonal) {
  return diagonal.minCoeff() <= 1e-10 * diagonal.maxCoeff();
}

// Errors of the first p terms on each fold, fitted on the other folds; nullopt when some
// training set cannot identify them.
std::optional<Errors> heldout_errors(const FitContext& context,
                                     const std::vector<std::pair<int, int>>& terms,
                                     Eigen::Index p) {
  Errors heldout;
  for (int f = 0; f < context.folds; ++f) {
    std::vector<const BlockFactor*> training;
    for (int g = 0; g < context.folds; ++g) {
      if (g != f) training.push_back(&context.fold_factors[static_cast<std::size_t>(g)]);
    }
    const BlockFactor trained = stack(training, context.p_all);
    if (trained.r.rows() < p) return std::nullopt;  // R has no p x p corner to read
    if (rank_deficient(diagonal_magnitudes(trained, p))) return std::nullopt;
    const Eigen::VectorXd fold_coefficients = solve_prefix(trained, p);
    const Errors e = errors_of(context.data, f, context.folds, context.s, terms, fold_coefficients);
    heldout.sse += e.sse;
    heldout.sae += e.sae;
    heldout.n += e.n;
  }
  return heldout;
}

OrderCandidate candidate_of(int order, std::size_t p, std::size_t n, double sst,
                            const Errors& in_sample, const Errors& heldout) {
  OrderCandidate candidate;
  candidate.order = order;
  candidate.terms = p;
  const double r2 = sst > 0.0 ? 1.0 - in_sample.sse / sst : 0.0;
  candidate.stats.r = std::sqrt(std::max(0.0, r2));
  candidate.stats.adjusted_r2 =
      1.0 - (1.0 - r2) * static_cast<double>(n - 1) / static_cast<double>(n - p);
  candidate.stats.rmse_mm = std::sqrt(in_sample.sse / static_cast<double>(n));
  candidate.stats.mae_mm = in_sample.sae / static_cast<double>(n);
  candidate.stats.heldout_mae_mm = heldout.sae / static_cast<double>(heldout.n);
  candidate.stats.heldout_rmse_mm = std::sqrt(heldout.sse / static_cast<double>(heldout.n));
  return candidate;
}

struct OrderFit {
  OrderCandidate candidate;
  Eigen::VectorXd coefficients;
};

// The fit of one order, or nullopt when this and higher orders are not identifiable on this
// data; throws when not even the first order is.
std::optional<OrderFit> fit_order(const FitContext& context, int order) {
  const std::size_t n = context.data.clearance_mm.size();
  const std::vector<std::pair<int, int>> terms = regression_terms(order);
  const auto p = static_cast<Eigen::Index>(terms.size());
  if (static_cast<std::size_t>(p) + 2 > n) return std::nullopt;
  if (rank_deficient(diagonal_magnitudes(context.whole, p))) {
    if (order == kMinRegressionOrder) {
      throw InputError(
          "calibration data: rank deficient (voltage and temperature move together, so their "
          "effects cannot be told apart); measure over independent ranges of both");
    }
    return std::nullopt;
  }
  const Eigen::VectorXd coefficients = solve_prefix(context.whole, p);
  const Errors in_sample =
      errors_of(context.data, -1, context.folds, context.s, terms, coefficients);
  const std::optional<Errors> heldout = heldout_errors(context, terms, p);
  if (!heldout) {
    if (order == kMinRegressionOrder) {
      throw InputError(
          "calibration data: some cross-validation fold cannot identify even the first order "
          "(too little variation of voltage or temperature outside it); measure over wider "
          "ranges");
    }
    return std::nullopt;
  }
  return OrderFit{
      candidate_of(order, static_cast<std::size_t>(p), n, context.sst, in_sample, *heldout),
      coefficients};
}

struct OrderChoice {
  std::size_t chosen = 0;
  std::size_t thesis_choice = 0;  // the lowest order with r >= min_r
  bool thesis_rule_met = false;
};

// The thesis's rule first (lowest order with r >= min_r), then one more order at a time while
// the held-out MAE falls by more than min_heldout_gain_mm: over-fitting stops it.
OrderChoice choose_order(const std::vector<OrderCandidate>& candidates,
                         const RegressionOptions& options) {
  OrderChoice choice;
  std::size_t& chosen = choice.chosen;
  while (chosen + 1 < candidates.size() && candidates[chosen].stats.r < options.min_r) {
    ++chosen;
  }
  choice.thesis_rule_met = candidates[chosen].stats.r >= options.min_r;
  choice.thesis_choice = chosen;
  if (!choice.thesis_rule_met) {
    // No order reaches the threshold: take the best held-out error instead.
    for (std::size_t k = 0; k < candidates.size(); ++k) {
      if (candidates[k].stats.heldout_mae_mm < candidates[chosen].stats.heldout_mae_mm) {
        chosen = k;
      }
    }
  } else {
    auto worth_it = [&](const OrderCandidate& now, const OrderCandidate& next) {
      const double gain = now.stats.heldout_mae_mm - next.stats.heldout_mae_mm;
      return gain > options.min_heldout_gain_mm;
    };
    while (chosen + 1 < candidates.size() && worth_it(candidates[chosen], candidates[chosen + 1])) {
      ++chosen;
    }
  }
  return choice;
}

std::string selection_reason(const std::vector<OrderCandidate>& candidates,
                             const OrderChoice& choice, const RegressionOptions& options) {
  const OrderCandidate& best = candidates[choice.chosen];
  if (!choice.thesis_rule_met) {
    return fmt::format(
        "no order up to {} reaches r >= {} (best r = {:.4f}); order {} has the lowest held-out "
        "MAE",
        candidates.back().order, options.min_r, candidates.back().stats.r, best.order);
  }
  if (choice.chosen == choice.thesis_choice) {
    return fmt::format(
        "order {} is the lowest with r >= {} (r = {:.4f}); order {} would not cut the held-out "
        "MAE by more than {:g} um",
        best.order, options.min_r, best.stats.r, best.order + 1,
        options.min_heldout_gain_mm * 1000);
  }
  return fmt::format(
      "order {} reaches r >= {}; held-out MAE kept falling by more than {:g} um per order up to "
      "order {}",
      candidates[choice.thesis_choice].order, options.min_r, options.min_heldout_gain_mm * 1000,
      best.order);
}

}  // namespace

RegressionModel::RegressionModel(int order, VariableScaling scaling,
                                 Eigen::VectorXd scaled_coefficients)
    : order_(order),
      scaling_(scaling),
      scaled_(std::move(scaled_coefficients)),
      terms_(regression_terms(order)) {}

double RegressionModel::clearance_mm(double voltage_v, double temp_c) const {
  const std::vector<std::pair<int, int>>& terms = terms_;
  const double v = (voltage_v - scaling_.v_center) / scaling_.v_half;
  const double t = (temp_c - scaling_.t_center) / scaling_.t_half;
  double d = 0.0;
  for (std::size_t k = 0; k < terms.size(); ++k) {
    d += scaled_(static_cast<Eigen::Index>(k)) * monomial(v, t, terms[k]);
  }
  return d;
}

std::vector<double> RegressionModel::raw_coefficients() const {
  // Expand c (v')^i (t')^j with v' = (V - vc)/vh, t' = (T - tc)/th by the binomial theorem.
  const std::vector<std::pair<int, int>> terms = regression_terms(order_);
  std::vector<double> raw(terms.size(), 0.0);
  auto binomial = [](int n, int k) {
    double value = 1.0;
    for (int m = 1; m <= k; ++m) value = value * (n - k + m) / m;
    return value;
  };
  for (std::size_t k = 0; k < terms.size(); ++k) {
    const auto [i, j] = terms[k];
    for (int a = 0; a <= i; ++a) {
      for (int b = 0; b <= j; ++b) {
        // Term V^a T^b of the expansion.
        const double factor = scaled_(static_cast<Eigen::Index>(k)) * binomial(i, a) *
                              std::pow(-scaling_.v_center, i - a) / std::pow(scaling_.v_half, i) *
                              binomial(j, b) * std::pow(-scaling_.t_center, j - b) /
                              std::pow(scaling_.t_half, j);
        const auto at = std::find(terms.begin(), terms.end(), std::make_pair(a, b));
        raw[static_cast<std::size_t>(at - terms.begin())] += factor;
      }
    }
  }
  return raw;
}

RegressionFit fit_regression(const CalibrationData& data, const RegressionOptions& options) {
  require_fittable(data, options.folds);
  const FitContext context(data, options);
  RegressionFit fit;
  std::vector<Eigen::VectorXd> coefficients_by_order;
  for (int order = kMinRegressionOrder; order <= options.max_order; ++order) {
    std::optional<OrderFit> order_fit = fit_order(context, order);
    if (!order_fit) break;
    fit.candidates.push_back(order_fit->candidate);
    coefficients_by_order.push_back(std::move(order_fit->coefficients));
  }
  const OrderChoice choice = choose_order(fit.candidates, options);
  const OrderCandidate& best = fit.candidates[choice.chosen];
  fit.selection = selection_reason(fit.candidates, choice, options);
  fit.model = RegressionModel(best.order, context.s, coefficients_by_order[choice.chosen]);
  fit.stats = best.stats;
  return fit;
}

std::string RegressionModel::equation() const {
  const std::vector<std::pair<int, int>> terms = regression_terms(order());
  const std::vector<double> raw = raw_coefficients();
  std::string text;
  for (std::size_t k = 0; k < terms.size(); ++k) {
    std::string monomial;
    if (terms[k].first > 0)
      monomial += terms[k].first == 1 ? " V" : fmt::format(" V^{}", terms[k].first);
    if (terms[k].second > 0)
      monomial += terms[k].second == 1 ? " T" : fmt::format(" T^{}", terms[k].second);
    text += fmt::format("{}{:.6g}{}", k == 0 ? "" : (raw[k] < 0 ? " - " : " + "),
                        k == 0 ? raw[k] : std::abs(raw[k]), monomial);
  }
  return text;
}

}  // namespace flange::host
