// SPDX-License-Identifier: MIT
// The skew channel_skew makes between the voltage and temperature channels, on the session's
// clock (docs/sensor_twin.md): > 0, the temperature is the older; < 0, the voltage.
#pragma once

namespace flange::sim {

struct ChannelSkewLaw {
  double skew_s = 0.0;                 // at the session's start
  double drift_s_per_h = 0.0;          // how fast it changes
  double drift_change_s_per_h2 = 0.0;  // how fast that drift changes

  double at(double t_s) const {
    const double h = t_s / 3600.0;
    return skew_s + drift_s_per_h * h + drift_change_s_per_h2 * h * h;
  }
  bool drifts() const { return drift_s_per_h != 0.0 || drift_change_s_per_h2 != 0.0; }
  bool zero() const { return skew_s == 0.0 && !drifts(); }
};

}  // namespace flange::sim
