// SPDX-License-Identifier: MIT
#include "compression_surface_family.h"

#include <fmt/format.h>

#include <algorithm>

#include "family_makers.h"
#include "ridge_solve.h"

namespace flange::diagnose::free_shapes {
namespace {

// Knots of the surface: five in voltage over the top of the range (the lowest held at 0), three
// in temperature.
constexpr int kVoltKnots = 5;
constexpr int kTempKnots = 3;

}  // namespace

CompressionSurfaceFamily::CompressionSurfaceFamily(const RecordedPart& calibration)
    : temp_(hats_over(calibration.series.temp_c, kTempKnots)) {
  const auto [lo, hi] = std::minmax_element(calibration.replay.nominal_voltage().begin(),
                                            calibration.replay.nominal_voltage().end());
  const double top = *hi, bottom = *hi - 0.4 * (*hi - *lo);
  for (int k = 0; k < kVoltKnots; ++k) {
    volt_.knots.push_back(bottom + (top - bottom) * k / (kVoltKnots - 1.0));
  }
}

void CompressionSurfaceFamily::search(const RecordedPart& calibration,
                                      const std::vector<double>& gap_v) {
  const Eigen::VectorXd y =
      Eigen::Map<const Eigen::VectorXd>(gap_v.data(), static_cast<Eigen::Index>(gap_v.size()));
  const Eigen::MatrixXd surface = columns(calibration);
  const auto nt = static_cast<Eigen::Index>(temp_.knots.size());
  Eigen::MatrixXd curve = matrix(gap_v.size(), volt_.knots.size() - 1);
  for (Eigen::Index j = 0; j < curve.cols(); ++j) {
    curve.col(j) = surface.middleCols(j * nt, nt).rowwise().sum();
  }
  const double with_t = (y - surface * ridge_solve(surface, y)).squaredNorm();
  const double without_t = (y - curve * ridge_solve(curve, y)).squaredNorm();
  temperature_matters_ = without_t - with_t > kLeastShareForATemperatureDependence * with_t;
}

std::vector<std::string> CompressionSurfaceFamily::names() const {
  std::vector<std::string> out;
  for (std::size_t j = 1; j < volt_.knots.size(); ++j) {
    for (double t : temp_.knots) {
      out.push_back(fmt::format("offset_v_at_{:.3g}v_{:.3g}c", volt_.knots[j], t));
    }
  }
  return out;
}

Eigen::MatrixXd CompressionSurfaceFamily::columns(const RecordedPart& part) const {
  const std::size_t n = part.series.size(), nt = temp_.knots.size();
  Eigen::MatrixXd a = matrix(n, (volt_.knots.size() - 1) * nt);
  for (std::size_t i = 0; i < n; ++i) {
    const double v = part.replay.nominal_voltage()[i];
    if (v <= volt_.knots.front()) continue;  // below the knee region: 0
    for (std::size_t j = 1; j < volt_.knots.size(); ++j) {
      const double wv = volt_.weight(j, v);
      if (wv == 0.0) continue;
      for (std::size_t k = 0; k < nt; ++k) {
        a(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>((j - 1) * nt + k)) =
            wv * temp_.weight(k, part.series.temp_c[i]);
      }
    }
  }
  return a;
}

std::string CompressionSurfaceFamily::describe(const Eigen::VectorXd& beta) const {
  const std::size_t nt = temp_.knots.size();
  std::string text = fmt::format(
      "a free surface over the top of the range (above {:.3g} V{}):", volt_.knots.front(),
      temperature_matters_ ? ""
                           : "; it does not change with temperature by more than the noise can "
                             "tell: alike a static nonlinearity of V");
  for (std::size_t k = 0; k < nt; ++k) {
    text += fmt::format("{} at {:.3g} degC {:.3g} V at the top", k == 0 ? "" : ";", temp_.knots[k],
                        beta(static_cast<Eigen::Index>((volt_.knots.size() - 2) * nt + k)));
  }
  return text;
}

std::unique_ptr<Family> make_compression_surface(const RecordedPart& calibration) {
  return std::make_unique<CompressionSurfaceFamily>(calibration);
}

}  // namespace flange::diagnose::free_shapes
