// SPDX-License-Identifier: MIT
#include "free_shape_fit.h"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <stdexcept>

namespace flange::diagnose {
namespace {

// Knots: enough to bend twice over a heating cycle or the voltage range, few enough that each
// holds thousands of samples of a bench session.
constexpr int kKnots = 7;

// Piecewise-linear "hat" functions on evenly spread knots: hat k is 1 at knot k, 0 at the others;
// beyond the ends the end hats stay at 1 (the curve is held constant there).
struct Hats {
  std::vector<double> knots;
  double weight(std::size_t k, double x) const {
    const double lo = knots.front(), hi = knots.back();
    x = std::clamp(x, lo, hi);
    const double step = (hi - lo) / static_cast<double>(knots.size() - 1);
    const double u = step > 0.0 ? (x - lo) / step : 0.0;
    return std::max(0.0, 1.0 - std::abs(u - static_cast<double>(k)));
  }
};

Hats hats_over(const std::vector<double>& x) {
  const auto [lo, hi] = std::minmax_element(x.begin(), x.end());
  Hats hats;
  for (int k = 0; k < kKnots; ++k) {
    hats.knots.push_back(*lo + (*hi - *lo) * k / static_cast<double>(kKnots - 1));
  }
  return hats;
}

// The family's columns at every sample: which hats it uses and what multiplies them.
struct Family {
  std::string variable;
  Hats hats;
  std::vector<std::size_t> used;  // hat indices with a free value
};

Family family_for(const std::string& effect, const RecordingSeries& calibration,
                  const TwinReplay& cal_replay) {
  if (effect == "nonlinearity") {
    Family f{"V", hats_over(cal_replay.nominal_voltage()), {}};
    for (std::size_t k = 1; k + 1 < kKnots; ++k) f.used.push_back(k);  // 0 at both ends
    return f;
  }
  if (effect == "temp_offset_drift" || effect == "temp_gain_drift") {
    Family f{effect == "temp_offset_drift" ? "T" : "(V - v_min) T", hats_over(calibration.temp_c),
             {}};
    for (std::size_t k = 0; k < kKnots; ++k) f.used.push_back(k);
    return f;
  }
  throw std::invalid_argument("no free-shape family for effect '" + effect + "'");
}

// The design matrix of `family` on one part.
Eigen::MatrixXd columns(const Family& family, const std::string& effect,
                        const RecordingSeries& series, const TwinReplay& replay, double v_min_v) {
  const std::size_t n = series.size();
  Eigen::MatrixXd a(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(family.used.size()));
  for (std::size_t i = 0; i < n; ++i) {
    const double v = replay.nominal_voltage()[i];
    const double x = effect == "nonlinearity" ? v : series.temp_c[i];
    const double scale = effect == "temp_gain_drift" ? v - v_min_v : 1.0;
    for (std::size_t j = 0; j < family.used.size(); ++j) {
      a(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) =
          scale * family.hats.weight(family.used[j], x);
    }
  }
  return a;
}

std::vector<double> as_vector(const Eigen::VectorXd& v) {
  return std::vector<double>(v.data(), v.data() + v.size());
}

}  // namespace

const std::vector<std::string>& free_shape_effects() {
  static const std::vector<std::string> effects = {"temp_gain_drift", "temp_offset_drift",
                                                   "nonlinearity"};
  return effects;
}

FreeShapeFit fit_free_shape(const std::string& effect, const RecordingSeries& calibration,
                            const TwinReplay& cal_replay, const RecordingSeries& heldout,
                            const TwinReplay& ho_replay, const std::vector<double>& cal_gap_v,
                            double v_min_v) {
  const Family family = family_for(effect, calibration, cal_replay);
  const Eigen::MatrixXd cal = columns(family, effect, calibration, cal_replay, v_min_v);
  const Eigen::Map<const Eigen::VectorXd> gap(cal_gap_v.data(),
                                              static_cast<Eigen::Index>(cal_gap_v.size()));
  // Column-pivoting QR: a hat with no samples under it (a temperature never visited) gets 0.
  const Eigen::VectorXd beta = cal.colPivHouseholderQr().solve(gap);
  FreeShapeFit fit;
  fit.effect = effect;
  fit.variable = family.variable;
  fit.knots = family.hats.knots;
  fit.values.assign(family.hats.knots.size(), 0.0);
  for (std::size_t j = 0; j < family.used.size(); ++j) {
    fit.values[family.used[j]] = beta(static_cast<Eigen::Index>(j));
  }
  fit.cal_voltage_v = as_vector(cal * beta);
  fit.heldout_voltage_v =
      as_vector(columns(family, effect, heldout, ho_replay, v_min_v) * beta);
  return fit;
}

std::map<std::string, double> FreeShapeFit::params() const {
  std::map<std::string, double> p;
  const bool in_volts = variable == "V";
  for (std::size_t k = 0; k < knots.size(); ++k) {
    p[fmt::format("{}_at_{:.4g}{}", effect == "temp_gain_drift" ? "gain_change" : "offset_v",
                  knots[k], in_volts ? "v" : "c")] = values[k];
  }
  return p;
}

std::string FreeShapeFit::describe() const {
  std::string text = fmt::format("a free curve of {} through", variable == "(V - v_min) T"
                                                                   ? "T (a gain about v_min)"
                                                                   : variable);
  const char* unit = variable == "V" ? "V" : "degC";
  for (std::size_t k = 0; k < knots.size(); ++k) {
    text += fmt::format("{} {:.3g} at {:.4g} {}", k == 0 ? "" : ",", values[k], knots[k], unit);
  }
  return text;
}

}  // namespace flange::diagnose
