// SPDX-License-Identifier: MIT
#include "moving_knee_family.h"

#include <fmt/format.h>

#include <algorithm>
#include <limits>

#include "family_makers.h"
#include "ridge_solve.h"

namespace flange::diagnose::free_shapes {
namespace {

// Knots of the knee's curve of temperature, and of the curve above the knee.
constexpr int kKneeTempKnots = 9;
constexpr int kKneeHeightKnots = 7;
// How far the curve above the knee goes on beyond the calibration part's highest point, in knot
// spacings, before it is held: six, the calibration's own height above the knee again, for a
// held-out session that heats further and so goes further above a knee that falls.
constexpr double kHeightReach = 6.0;
// The knee's search, in shares of the span it may take (from the top of the range down to the
// lowest knee allowed). The lattice: its cold value in eighths, and falls of a quarter of the
// span to all of it, spread evenly from an onset knot to the hot end; it only has to land in the
// basin the refinement descends. The best knee that does not move, to a 64th of the span: what a
// moving one must beat, found finer than the lattice so that a moving knee is not credited with
// the lattice's coarseness. The pattern refinement's steps, a tenth of the span down to 0.6 %.
constexpr double kColdStep = 0.125;
constexpr double kFallStep = 0.25;
constexpr double kFlatStep = 1.0 / 64.0;
constexpr double kPatternSteps[] = {0.1, 0.025, 0.006};

}  // namespace

MovingKneeFamily::MovingKneeFamily(const RecordedPart& calibration)
    : temp_(hats_over(calibration.series.temp_c, kKneeTempKnots)) {
  temp_.reach_both(kTemperatureReach);
  const auto [lo, hi] = std::minmax_element(calibration.replay.nominal_voltage().begin(),
                                            calibration.replay.nominal_voltage().end());
  top_v_ = *hi;
  lowest_knee_v_ = *hi - 0.6 * (*hi - *lo);
  knee_v_.assign(temp_.knots.size(), top_v_);
}

// On a long log, the rows a parameter search runs on (TwinReplay::search_replay). Rows at or
// below the lowest knee allowed are 0 in every column whatever the knee, so they add the same to
// every candidate's sum of squares and are left out of the search.
MovingKneeFamily::SearchRows MovingKneeFamily::search_rows(const RecordedPart& calibration,
                                                           const std::vector<double>& gap_v) const {
  const TwinReplay& replay = calibration.replay.search_replay();
  const std::vector<double> gap = calibration.replay.at_search_rows(gap_v);
  std::vector<double> volts, temps, gap_above;
  for (std::size_t i = 0; i < gap.size(); ++i) {
    if (replay.nominal_voltage()[i] <= lowest_knee_v_) continue;
    volts.push_back(replay.nominal_voltage()[i]);
    temps.push_back(replay.series().temp_c[i]);
    gap_above.push_back(gap[i]);
  }
  return {volts, knee_places(temps),
          Eigen::Map<const Eigen::VectorXd>(gap_above.data(),
                                            static_cast<Eigen::Index>(gap_above.size()))};
}

// The knee as its cold value and the non-negative falls between neighbouring knots: a knee that
// only falls as the coil heats, flat up to wherever the compression sets in.
std::vector<double> MovingKneeFamily::knee_of(const std::vector<double>& law) const {
  std::vector<double> knee(law.size());
  double k = std::clamp(law[0], lowest_knee_v_, top_v_);
  for (std::size_t j = 0; j < law.size(); ++j) {
    if (j > 0) k -= std::max(0.0, law[j]);
    knee[j] = std::max(k, lowest_knee_v_);
  }
  return knee;
}

std::vector<double> MovingKneeFamily::flat_law(double cold) const {
  std::vector<double> flat(knee_v_.size(), 0.0);
  flat[0] = top_v_ - cold * (top_v_ - lowest_knee_v_);
  return flat;
}

// Knees flat up to an onset knot and falling evenly from there to the hot end, each cold value's
// followed by the knee that does not move.
std::vector<std::vector<double>> MovingKneeFamily::lattice_of_laws() const {
  const double span = top_v_ - lowest_knee_v_;
  const std::size_t knots = knee_v_.size();
  std::vector<std::vector<double>> laws;
  for (double cold : stepped_axis(0.0, 1.0 + 1e-9, kColdStep)) {
    for (std::size_t onset = 0; onset + 1 < knots; ++onset) {
      for (double fall : stepped_axis(kFallStep, 1.0 + 1e-9, kFallStep)) {
        std::vector<double> law(knots, 0.0);
        law[0] = top_v_ - cold * span;
        for (std::size_t j = onset + 1; j < knots; ++j) {
          law[j] = fall * span / static_cast<double>(knots - 1 - onset);
        }
        laws.push_back(std::move(law));
      }
    }
    laws.push_back(flat_law(cold));
  }
  return laws;
}

// For each knot and each way: one fall moved (every hotter knot with it), then that knot alone
// (its fall and the next one's trade). Falls stay non-negative.
std::vector<PatternMove> MovingKneeFamily::law_moves() const {
  const std::size_t knots = knee_v_.size();
  std::vector<PatternMove> moves;
  for (std::size_t k = 0; k < knots; ++k) {
    for (double sign : {-1.0, 1.0}) {
      moves.push_back([k, sign](const std::vector<double>& from, double step) {
        std::vector<double> trial = from;
        trial[k] += sign * step;
        if (k > 0 && trial[k] < 0.0) return std::optional<std::vector<double>>();
        return std::optional<std::vector<double>>(std::move(trial));
      });
      if (k == 0 || k + 1 >= knots) continue;
      moves.push_back([k, sign](const std::vector<double>& from, double step) {
        std::vector<double> trial = from;
        trial[k] += sign * step;
        trial[k + 1] -= sign * step;
        if (trial[k] < 0.0 || trial[k + 1] < 0.0) return std::optional<std::vector<double>>();
        return std::optional<std::vector<double>>(std::move(trial));
      });
    }
  }
  return moves;
}

void MovingKneeFamily::search(const RecordedPart& calibration, const std::vector<double>& gap_v) {
  const SearchRows rows = search_rows(calibration, gap_v);
  double best_flat = std::numeric_limits<double>::infinity();  // the least a fixed knee leaves
  const Objective sse_of = [&](const std::vector<double>& law) {
    knee_v_ = knee_of(law);
    const double sse = least_squares_sse(rows);
    if (knee_v_.front() == knee_v_.back()) best_flat = std::min(best_flat, sse);
    return sse;
  };
  SearchPoint best{std::vector<double>(knee_v_.size(), 0.0)};
  best.at[0] = top_v_;
  search_points(lattice_of_laws(), sse_of, best);
  for (double cold : stepped_axis(0.0, 1.0 + 1e-9, kFlatStep)) sse_of(flat_law(cold));
  const double span = top_v_ - lowest_knee_v_;
  std::vector<double> steps;
  for (double share : kPatternSteps) steps.push_back(share * span);
  refine_by_pattern(steps, law_moves(), sse_of, best);
  knee_v_ = knee_of(best.at);
  least_squares_sse(rows);  // sets height_span_v_ for the chosen knee
  knee_moves_ = best_flat - best.value > kLeastShareForATemperatureDependence * best.value;
}

std::vector<std::string> MovingKneeFamily::names() const {
  std::vector<std::string> out;
  for (std::size_t j = 1; j < kKneeHeightKnots; ++j) {
    out.push_back(fmt::format("offset_v_at_{:.3g}v_above_knee", height_knot(j)));
  }
  return out;
}

Eigen::MatrixXd MovingKneeFamily::columns(const RecordedPart& part) const {
  return columns_of(part.replay.nominal_voltage(), part.series.temp_c);
}

void MovingKneeFamily::summarise(const Eigen::VectorXd&, const RecordedPart&,
                                 std::map<std::string, double>& params) const {
  for (std::size_t k = 0; k < knee_v_.size(); ++k) {
    params[fmt::format("knee_v_at_{:.3g}c", temp_.knots[k])] = knee_v_[k];
  }
}

std::string MovingKneeFamily::describe(const Eigen::VectorXd& beta) const {
  std::string text = "a compression above a knee that moves with temperature: knee";
  for (std::size_t k = 0; k < knee_v_.size(); ++k) {
    text +=
        fmt::format("{} {:.3g} V at {:.3g} degC", k == 0 ? "" : ",", knee_v_[k], temp_.knots[k]);
  }
  text += knee_moves_ ? "; above it"
                      : " (it does not move with temperature by more than the noise can tell: a "
                        "fixed knee, alike a static nonlinearity of V above it); above it";
  for (std::size_t j = 1; j < kKneeHeightKnots; ++j) {
    text += fmt::format("{} {:.3g} V at {:.3g} V over", j == 1 ? "" : ",",
                        beta(static_cast<Eigen::Index>(j - 1)), height_knot(j));
  }
  return text;
}

std::vector<MovingKneeFamily::KneePlace> MovingKneeFamily::knee_places(
    const std::vector<double>& temps) const {
  const double lo = temp_.knots.front(), hi = temp_.knots.back();
  const double last = static_cast<double>(temp_.knots.size() - 1);
  std::vector<KneePlace> places(temps.size());
  for (std::size_t i = 0; i < temps.size(); ++i) {
    const double u = hi > lo ? std::clamp((temps[i] - lo) / (hi - lo) * last, 0.0, last) : 0.0;
    places[i].k = std::min(static_cast<std::size_t>(u), temp_.knots.size() - 2);
    places[i].f = u - static_cast<double>(places[i].k);
  }
  return places;
}

// For the knee the search holds: the highest point above it (height_span_v_), then the sum of
// squares the ridge fit of the rows' gap on columns_of(volts, temps) leaves, from the normal
// equations summed row by row (a row has at most two hats that are not 0): what the search
// evaluates hundreds of times, without the rows x columns matrix. The same numbers as the hats
// give, with each row's place among the knots worked out once (SearchRows::places).
double MovingKneeFamily::least_squares_sse(const SearchRows& rows) {
  constexpr int kCols = kKneeHeightKnots - 1;
  const std::vector<double>& volts = rows.volts;
  const Eigen::VectorXd& y = rows.gap;
  std::vector<double> over(volts.size());
  double most = 1e-3;
  for (std::size_t i = 0; i < volts.size(); ++i) {
    const KneePlace& p = rows.places[i];
    over[i] = volts[i] - (knee_v_[p.k] * (1.0 - p.f) + knee_v_[p.k + 1] * p.f);
    most = std::max(most, over[i]);
  }
  height_span_v_ = most;
  const double per_knot = static_cast<double>(kCols) / most;
  Eigen::Matrix<double, kCols, kCols> normal = Eigen::Matrix<double, kCols, kCols>::Zero();
  Eigen::Matrix<double, kCols, 1> aty = Eigen::Matrix<double, kCols, 1>::Zero();
  for (std::size_t i = 0; i < volts.size(); ++i) {
    if (over[i] <= 0.0) continue;
    const double u = std::min(over[i] * per_knot, static_cast<double>(kCols));
    const int k = std::min(static_cast<int>(u), kCols - 1);  // between hats k and k + 1
    const double f = u - k, yi = y(static_cast<Eigen::Index>(i));
    // Hat k + 1 is column k; hat k is column k - 1 (hat 0, at the knee, is no column).
    aty(k) += f * yi;
    normal(k, k) += f * f;
    if (k > 0) {
      const double g = 1.0 - f;
      aty(k - 1) += g * yi;
      normal(k - 1, k - 1) += g * g;
      normal(k - 1, k) += g * f;
      normal(k, k - 1) += g * f;
    }
  }
  Eigen::Matrix<double, kCols, kCols> ridged = normal;
  const double largest = normal.diagonal().maxCoeff();
  for (int c = 0; c < kCols; ++c) {
    ridged(c, c) += kRidge * normal(c, c) + 1e-12 * std::max(largest, 1e-300);
  }
  const Eigen::Matrix<double, kCols, 1> beta = ridged.ldlt().solve(aty);
  return y.squaredNorm() - 2.0 * beta.dot(aty) + beta.dot(normal * beta);
}

Eigen::MatrixXd MovingKneeFamily::columns_of(const std::vector<double>& volts,
                                             const std::vector<double>& temps) const {
  const std::size_t n = volts.size();
  Eigen::MatrixXd a = matrix(n, kKneeHeightKnots - 1);
  const Hats heights = height_hats();
  for (std::size_t i = 0; i < n; ++i) {
    const double over = volts[i] - knee_at(temps[i]);
    if (over <= 0.0) continue;
    for (std::size_t j = 1; j < kKneeHeightKnots; ++j) {
      a(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j - 1)) = heights.weight(j, over);
    }
  }
  return a;
}

double MovingKneeFamily::knee_at(double temp_c) const {
  double k = 0.0;
  for (std::size_t j = 0; j < knee_v_.size(); ++j) k += knee_v_[j] * temp_.weight(j, temp_c);
  return k;
}

// Knots of h, evenly from the knee to the most the calibration part goes above it.
double MovingKneeFamily::height_knot(std::size_t j) const {
  return height_span_v_ * static_cast<double>(j) / (kKneeHeightKnots - 1.0);
}

Hats MovingKneeFamily::height_hats() const {
  Hats h;
  for (std::size_t j = 0; j < kKneeHeightKnots; ++j) h.knots.push_back(height_knot(j));
  h.reach_both(kHeightReach);
  return h;
}

std::unique_ptr<Family> make_moving_knee(const RecordedPart& calibration) {
  return std::make_unique<MovingKneeFamily>(calibration);
}

}  // namespace flange::diagnose::free_shapes
