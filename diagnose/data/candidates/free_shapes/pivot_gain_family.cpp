// SPDX-License-Identifier: MIT
#include "pivot_gain_family.h"

#include <fmt/format.h>

#include "family_makers.h"
#include "ridge_solve.h"

namespace flange::diagnose::free_shapes {

PivotGainFamily::PivotGainFamily(const RecordedPart& calibration)
    : hats_(hats_over(calibration.series.temp_c, kKnots)) {
  hats_.reach_both(kTemperatureReach);
}

void PivotGainFamily::search(const RecordedPart& calibration, const std::vector<double>& gap_v) {
  choose_temperature_reach(hats_, calibration, gap_v, [&](const Hats& hats) {
    PivotGainFamily with = *this;
    with.hats_ = hats;
    return with.columns(calibration);
  });
}

std::vector<std::string> PivotGainFamily::names() const {
  std::vector<std::string> out;
  for (double knot : hats_.knots) out.push_back(fmt::format("gain_change_at_{:.4g}c", knot));
  for (double knot : hats_.knots) out.push_back(fmt::format("offset_v_at_{:.4g}c", knot));
  return out;
}

Eigen::MatrixXd PivotGainFamily::columns(const RecordedPart& part) const {
  const std::size_t n = part.series.size(), k = hats_.knots.size();
  Eigen::MatrixXd a = matrix(n, 2 * k);
  for (std::size_t i = 0; i < n; ++i) {
    const double above = part.replay.nominal_voltage()[i] - part.replay.v_min_v();
    const auto row = static_cast<Eigen::Index>(i);
    // Off the hats' support a weight is +0.0 (hats.h), its gain column above * +0.0.
    if (std::signbit(above)) a.row(row).head(static_cast<Eigen::Index>(k)).setConstant(above * 0.0);
    const auto [first, last] = hats_.support(part.series.temp_c[i]);
    for (std::size_t j = first; j <= last; ++j) {
      const double w = hats_.weight(j, part.series.temp_c[i]);
      a(row, static_cast<Eigen::Index>(j)) = above * w;
      a(row, static_cast<Eigen::Index>(k + j)) = w;
    }
  }
  return a;
}

void PivotGainFamily::summarise(const Eigen::VectorXd& beta, const RecordedPart& calibration,
                                std::map<std::string, double>& params) const {
  const auto k = static_cast<Eigen::Index>(hats_.knots.size());
  const Eigen::VectorXd gain = beta.head(k), offset = beta.tail(k);
  const double norm = gain.squaredNorm();
  if (norm > 0.0) params["pivot_v"] = calibration.replay.v_min_v() - gain.dot(offset) / norm;
}

std::string PivotGainFamily::describe(const Eigen::VectorXd& beta) const {
  const auto k = static_cast<Eigen::Index>(hats_.knots.size());
  std::string text = "a gain that changes with T about a pivot of its own: gain change";
  for (Eigen::Index j = 0; j < k; ++j) {
    text += fmt::format("{} {:.3g} at {:.4g} degC", j == 0 ? "" : ",", beta(j),
                        hats_.knots[static_cast<std::size_t>(j)]);
  }
  return text;
}

std::unique_ptr<Family> make_pivot_gain(const RecordedPart& calibration) {
  return std::make_unique<PivotGainFamily>(calibration);
}

}  // namespace flange::diagnose::free_shapes
