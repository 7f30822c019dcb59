// SPDX-License-Identifier: MIT
// A compression above a knee that moves with temperature: V' - V = h(max(0, V - k(T))), with the
// knee k(T) any falling piecewise-linear curve through nine temperatures of the calibration part
// (searched) and h any curve of the height above it, 0 at the knee. The library's compression (a
// knee falling linearly with T, tanh above it) is one member; so is a knee that falls along an
// exponential or a parabola, with any saturating or linear law above it. The knee stays in the
// top three fifths of the voltage range: lower, h(V - k(T)) would be a gain and an offset of T.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "family.h"
#include "grid_search.h"
#include "hats.h"

namespace flange::diagnose::free_shapes {

class MovingKneeFamily : public LinearFamily {
 public:
  explicit MovingKneeFamily(const RecordedPart& calibration);

  // The knee's law (searched: grid_search.h) on the calibration part's search rows, and whether
  // its moving earns its place (kLeastShareForATemperatureDependence against the best knee that
  // does not move).
  void search(const RecordedPart& calibration, const std::vector<double>& gap_v) override;
  // A knee that does not move with temperature, or moves without earning it, makes h(V - k) a
  // curve of V alone above a fixed voltage: a static nonlinearity, not a range compression (the
  // class is "the top of the range, temperature dependent").
  bool shape_is_function_of_clearance_alone() const override { return !knee_moves_; }
  int searched_values() const override { return static_cast<int>(knee_v_.size()); }
  std::vector<std::string> names() const override;
  Eigen::MatrixXd columns(const RecordedPart& part) const override;
  void summarise(const Eigen::VectorXd& beta, const RecordedPart& calibration,
                 std::map<std::string, double>& params) const override;
  std::string describe(const Eigen::VectorXd& beta) const override;

  // The knee at each of the temperature knots, and those knots.
  const std::vector<double>& knee_v() const { return knee_v_; }
  const std::vector<double>& temperature_knots_c() const { return temp_.knots; }
  bool knee_moves() const { return knee_moves_; }

 private:
  // Where a calibration temperature falls among the knee's knots: knot k and the fraction f of
  // the way to knot k + 1 (the search's temperatures lie within the knots).
  struct KneePlace {
    std::size_t k = 0;
    double f = 0.0;
  };
  // The search rows above the lowest knee allowed.
  struct SearchRows {
    std::vector<double> volts;
    std::vector<KneePlace> places;
    Eigen::VectorXd gap;
  };
  SearchRows search_rows(const RecordedPart& calibration, const std::vector<double>& gap_v) const;
  std::vector<KneePlace> knee_places(const std::vector<double>& temps) const;
  // A law: the knee's cold value, then the falls between neighbouring knots.
  std::vector<double> knee_of(const std::vector<double>& law) const;
  std::vector<double> flat_law(double cold) const;
  std::vector<std::vector<double>> lattice_of_laws() const;
  std::vector<PatternMove> law_moves() const;
  double least_squares_sse(const SearchRows& rows);
  Eigen::MatrixXd columns_of(const std::vector<double>& volts,
                             const std::vector<double>& temps) const;
  double knee_at(double temp_c) const;
  double height_knot(std::size_t j) const;
  Hats height_hats() const;

  Hats temp_;
  bool knee_moves_ = true;
  double top_v_ = 0.0, lowest_knee_v_ = 0.0, height_span_v_ = 1e-3;
  std::vector<double> knee_v_;
};

}  // namespace flange::diagnose::free_shapes
