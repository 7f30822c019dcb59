// SPDX-License-Identifier: MIT
// The coil at a temperature S T other than the recorded T, S any mix of first-order lags (the
// sensor lags: a mean delay tau_s > 0) and of advances of the recorded temperature (the reading
// lags: tau_s < 0): dV/dT (S T - T).
#pragma once

#include <array>
#include <map>
#include <string>
#include <vector>

#include "family.h"

namespace flange::diagnose::free_shapes {

class LagFamily : public LinearFamily {
 public:
  std::vector<std::string> names() const override;
  Eigen::MatrixXd columns(const RecordedPart& part) const override;
  // The mix's mean delay: each lag delays by its tau, each advance by minus its lead. A positive
  // one is the sensor lagging (the library's thermal_lag with tau_s > 0), a negative one the
  // reading lagging (tau_s < 0).
  void summarise(const Eigen::VectorXd& beta, const RecordedPart& calibration,
                 std::map<std::string, double>& params) const override;
  std::string describe(const Eigen::VectorXd& beta) const override;

  double mean_delay_s(const Eigen::VectorXd& beta) const;
  // The name of the free value that weighs the lag of `tau_s` ("weight_lag_240s").
  static std::string lag_weight_name(double tau_s);

  // Time constants and advances a factor of four apart, 30 s to 16 min: the bench's heating and
  // cooling take tens of minutes, so shorter ones look alike and longer ones exceed a session.
  static constexpr std::array<double, 3> kLags = {60.0, 240.0, 960.0};
  static constexpr std::array<double, 3> kLeads = {30.0, 120.0, 480.0};
};

// A voltage that follows how far the recorded temperature has run ahead of its own lags, with a
// scale of its own: A (S T - T), S a mix of the first-order lags of LagFamily and A volts per
// degC, not the coil's dV/dT. What the coil's temperature lagging cannot make (its scale is the
// sensor's sensitivity), but a housing or a mount that lags in the heat makes. Its summary is
// the mix's mean delay (delay_s, the weights' own mean, whatever their sign) and A (v_per_c); it
// has no tau_s, so the improved twin does not take it for the library's lag but holds it as the
// twin's thermal_lag_volts with the same lags (candidates/class_fits.cpp, lag_member). The lags
// are the twin's (sim::FirstOrderLag), so that the twin replays the shape as fitted.
class VoltsLagFamily : public LinearFamily {
 public:
  explicit VoltsLagFamily(const RecordedPart& calibration);
  std::vector<std::string> names() const override;
  Eigen::MatrixXd columns(const RecordedPart& part) const override;
  void summarise(const Eigen::VectorXd& beta, const RecordedPart& calibration,
                 std::map<std::string, double>& params) const override;
  std::string describe(const Eigen::VectorXd& beta) const override;

 private:
  std::map<std::string, double> summary(const Eigen::VectorXd& beta) const;
  // The calibration part's median |dV/dT|: the columns' scale, so that the ridge weighs this
  // family's weights as it weighs LagFamily's.
  double volts_per_c_scale_ = 0.0;
};

}  // namespace flange::diagnose::free_shapes
