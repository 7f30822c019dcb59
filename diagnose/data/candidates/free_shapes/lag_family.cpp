// SPDX-License-Identifier: MIT
#include "lag_family.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "family_makers.h"
#include "first_order_lag.h"
#include "ridge_solve.h"

namespace flange::diagnose::free_shapes {

std::vector<std::string> LagFamily::names() const {
  std::vector<std::string> out;
  for (double tau : kLags) out.push_back(lag_weight_name(tau));
  for (double lead : kLeads) out.push_back(fmt::format("weight_advance_{:g}s", lead));
  return out;
}

Eigen::MatrixXd LagFamily::columns(const RecordedPart& part) const {
  const std::vector<double>& t = part.series.t_s;
  const std::vector<double>& temp = part.series.temp_c;
  const std::vector<double>& dv_dt = part.replay.temperature_sensitivity_v_per_c();
  const std::size_t n = t.size();
  Eigen::MatrixXd a = matrix(n, kLags.size() + kLeads.size());
  for (std::size_t k = 0; k < kLags.size(); ++k) {
    // A first-order lag stepped by each sample's own interval (short against every tau).
    double lagged = temp.empty() ? 0.0 : temp.front();
    for (std::size_t i = 0; i < n; ++i) {
      if (i > 0) lagged += (temp[i] - lagged) * (1.0 - std::exp(-(t[i] - t[i - 1]) / kLags[k]));
      a(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k)) = dv_dt[i] * (lagged - temp[i]);
    }
  }
  for (std::size_t k = 0; k < kLeads.size(); ++k) {
    const auto col = static_cast<Eigen::Index>(kLags.size() + k);
    SeriesInterpolator ahead(t, temp);
    for (std::size_t i = 0; i < n; ++i) {
      a(static_cast<Eigen::Index>(i), col) = dv_dt[i] * (ahead.at(t[i] + kLeads[k]) - temp[i]);
    }
  }
  return a;
}

void LagFamily::summarise(const Eigen::VectorXd& beta, const RecordedPart&,
                          std::map<std::string, double>& params) const {
  params["tau_s"] = mean_delay_s(beta);
}

std::string LagFamily::describe(const Eigen::VectorXd& beta) const {
  std::string text = fmt::format(
      "the coil's temperature off the recorded one by a free mix of lags and advances (mean "
      "delay {:.0f} s; weights",
      mean_delay_s(beta));
  const std::vector<std::string> n = names();
  for (std::size_t j = 0; j < n.size(); ++j) {
    text += fmt::format("{} {} {:.2f}", j == 0 ? "" : ",", n[j].substr(7),
                        beta(static_cast<Eigen::Index>(j)));
  }
  return text + ")";
}

double LagFamily::mean_delay_s(const Eigen::VectorXd& beta) const {
  double delay = 0.0;
  for (std::size_t k = 0; k < kLags.size(); ++k) {
    delay += beta(static_cast<Eigen::Index>(k)) * kLags[k];
  }
  for (std::size_t k = 0; k < kLeads.size(); ++k) {
    delay -= beta(static_cast<Eigen::Index>(kLags.size() + k)) * kLeads[k];
  }
  return delay;
}

std::string LagFamily::lag_weight_name(double tau_s) {
  return fmt::format("weight_lag_{:g}s", tau_s);
}

std::unique_ptr<Family> make_lag(const RecordedPart&) { return std::make_unique<LagFamily>(); }

namespace {

double median_magnitude(std::vector<double> x) {
  if (x.empty()) return 0.0;
  for (double& v : x) v = std::abs(v);
  const auto mid = x.begin() + static_cast<std::ptrdiff_t>(x.size() / 2);
  std::nth_element(x.begin(), mid, x.end());
  return *mid;
}

}  // namespace

VoltsLagFamily::VoltsLagFamily(const RecordedPart& calibration)
    : volts_per_c_scale_(median_magnitude(calibration.replay.temperature_sensitivity_v_per_c())) {}

std::vector<std::string> VoltsLagFamily::names() const {
  std::vector<std::string> out;
  for (double tau : LagFamily::kLags) out.push_back(LagFamily::lag_weight_name(tau));
  return out;
}

Eigen::MatrixXd VoltsLagFamily::columns(const RecordedPart& part) const {
  const std::vector<double>& t = part.series.t_s;
  const std::vector<double>& temp = part.series.temp_c;
  const std::size_t n = t.size();
  Eigen::MatrixXd a = matrix(n, LagFamily::kLags.size());
  for (std::size_t k = 0; k < LagFamily::kLags.size(); ++k) {
    sim::FirstOrderLag lag(LagFamily::kLags[k]);
    for (std::size_t i = 0; i < n; ++i) {
      a(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k)) =
          volts_per_c_scale_ * (lag.step(t[i], temp[i]) - temp[i]);
    }
  }
  return a;
}

std::map<std::string, double> VoltsLagFamily::summary(const Eigen::VectorXd& beta) const {
  double sum = 0.0, moment = 0.0;
  for (std::size_t k = 0; k < LagFamily::kLags.size(); ++k) {
    sum += beta(static_cast<Eigen::Index>(k));
    moment += beta(static_cast<Eigen::Index>(k)) * LagFamily::kLags[k];
  }
  std::map<std::string, double> out{{"v_per_c", volts_per_c_scale_ * sum}};
  if (sum != 0.0) out["delay_s"] = moment / sum;
  return out;
}

void VoltsLagFamily::summarise(const Eigen::VectorXd& beta, const RecordedPart&,
                               std::map<std::string, double>& params) const {
  for (const auto& [key, value] : summary(beta)) params[key] = value;
}

std::string VoltsLagFamily::describe(const Eigen::VectorXd& beta) const {
  const std::map<std::string, double> s = summary(beta);
  return fmt::format(
      "a voltage of {:.4f} V per degC of the recorded temperature's lead over a free mix of its "
      "lags (mean delay {:.0f} s)",
      s.at("v_per_c"), s.count("delay_s") ? s.at("delay_s") : 0.0);
}

std::unique_ptr<Family> make_volts_lag(const RecordedPart& calibration) {
  return std::make_unique<VoltsLagFamily>(calibration);
}

}  // namespace flange::diagnose::free_shapes
