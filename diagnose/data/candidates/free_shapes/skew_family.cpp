// SPDX-License-Identifier: MIT
#include "skew_family.h"

#include <fmt/format.h>

#include "family_makers.h"
#include "grid_search.h"
#include "ridge_solve.h"
#include "sensor_age.h"

namespace flange::diagnose::free_shapes {
namespace {

// The lattice's spacing in s0 (s) and s1 (s/h): it only has to land in the basin of the true law,
// which the pattern's steps then descend to 0.02 s, well under a sample's interval at a bench's
// rates.
constexpr double kLatticeStep = 1.0;
constexpr double kPatternSteps[] = {0.5, 0.1, 0.02};

}  // namespace

void SkewFamily::search(const RecordedPart& calibration, const std::vector<double>& gap_v) {
  // On a long log, the rows a parameter search runs on (TwinReplay::search_replay).
  const TwinReplay& rows = calibration.replay.search_replay();
  const RecordedPart part{rows.series(), rows};
  const std::vector<double> gap = calibration.replay.at_search_rows(gap_v);
  const Objective sse_of = [&](const std::vector<double>& at) {
    const std::vector<double> shifted = shift(part, {at[0], at[1], at[2]});
    double sse = 0.0;
    for (std::size_t i = 0; i < gap.size(); ++i) {
      const double e = gap[i] - shifted[i];
      sse += e * e;
    }
    return sse;
  };
  // The lattice's points over the worker threads, then the pattern's steps one by one.
  SearchPoint best{{law_[0], law_[1], law_[2]}};
  search_points_at_once(
      lattice({stepped_axis(-kMaxSkewS, kMaxSkewS + 1e-9, kLatticeStep),
               stepped_axis(-kMaxDriftSPerHour, kMaxDriftSPerHour + 1e-9, kLatticeStep),
               {0.0}}),
      sse_of, best);
  refine_by_pattern({std::begin(kPatternSteps), std::end(kPatternSteps)}, coordinate_moves(3),
                    sse_of, best);
  law_ = {best.at[0], best.at[1], best.at[2]};
}

Eigen::MatrixXd SkewFamily::columns(const RecordedPart& part) const {
  const std::vector<double> shifted = shift(part, law_);
  Eigen::MatrixXd a = matrix(shifted.size(), 1);
  for (std::size_t i = 0; i < shifted.size(); ++i) {
    a(static_cast<Eigen::Index>(i), 0) = shifted[i];
  }
  return a;
}

void SkewFamily::summarise(const Eigen::VectorXd&, const RecordedPart& calibration,
                           std::map<std::string, double>& params) const {
  const std::vector<double>& t = calibration.series.t_s;
  const double end_h = t.empty() ? 0.0 : t.back() / kSecondsPerHour;
  params["skew_s_at_start"] = skew_at(0.0);
  params["skew_s_at_end"] = skew_at(end_h);
  params["skew_s"] = skew_at(0.5 * end_h);
  // The law itself, and where over the session the skew comes nearest to a late temperature
  // channel (its largest value: the ends, or the parabola's vertex between them).
  params["drift_s_per_h"] = law_[1];
  params["drift_change_s_per_h2"] = law_[2];
  double most = std::max(skew_at(0.0), skew_at(end_h));
  if (law_[2] != 0.0) {
    const double vertex_h = -law_[1] / (2.0 * law_[2]);
    if (vertex_h > 0.0 && vertex_h < end_h) most = std::max(most, skew_at(vertex_h));
  }
  params["skew_s_most"] = most;
}

std::string SkewFamily::describe(const Eigen::VectorXd& beta) const {
  return fmt::format(
      "the voltage channel off in time by a skew that drifts: {:.3g} s + {:.3g} s/h t + {:.3g} "
      "s/h^2 t^2 (negative: late; scale {:.2f})",
      law_[0], law_[1], law_[2], beta(0));
}

std::vector<double> SkewFamily::shift(const RecordedPart& part, const std::array<double, 3>& law) {
  const std::vector<double>& t = part.series.t_s;
  const std::vector<double>& v = part.replay.nominal_voltage();
  std::vector<double> out(t.size());
  std::size_t j = 0;  // the sample at or before the shifted instant (it moves forward)
  for (std::size_t i = 0; i < t.size(); ++i) {
    const double h = t[i] / kSecondsPerHour;
    const double when = t[i] + law[0] + law[1] * h + law[2] * h * h;
    while (j > 0 && t[j] > when) --j;
    while (j + 1 < t.size() && t[j + 1] <= when) ++j;
    if (when <= t.front()) {
      out[i] = v.front() - v[i];
    } else if (j + 1 >= t.size()) {
      out[i] = v.back() - v[i];
    } else {
      const double w = (when - t[j]) / (t[j + 1] - t[j]);
      out[i] = v[j] + w * (v[j + 1] - v[j]) - v[i];
    }
  }
  return out;
}

std::unique_ptr<Family> make_skew(const RecordedPart&) { return std::make_unique<SkewFamily>(); }

}  // namespace flange::diagnose::free_shapes
