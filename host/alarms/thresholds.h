// SPDX-License-Identifier: MIT
// The threshold stage: flange thickness from clearance, warning and critical alarms with
// hysteresis and a minimum dwell, and the thesis's wear-step check R_T <= h (eqs. 3.37-3.38).
#pragma once

#include <optional>
#include <string>

namespace flange::host {

// Every threshold is configurable; defaults are the thesis's (section 3.4).
struct ThresholdConfig {
  double flange_nominal_mm = 33.0;    // new flange thickness
  double sensor_gap_mm = 2.0;         // clearance at which the sensor was set on a new flange
  double warning_clearance_mm = 8.0;  // 6 mm of wear: a 27 mm flange
  double critical_flange_mm = 25.0;   // continuous critical alarm at or below this thickness
  double hysteresis_mm = 0.1;         // an alarm clears only this far back on the safe side
  double min_dwell_s = 2.0;           // a condition must hold this long to change the alarm
  bool latch_critical = true;         // critical stays on until reset (section 3.4: continuous)
  double max_step_mm = 0.5;           // h of eq. 3.38: largest wear between two measurements
  double step_window_s = 60.0;        // one "measurement" d_f of eq. 3.37: a window's mean
};

// Throws InputError naming the field and its valid range.
void validate(const ThresholdConfig& config);

enum class AlarmLevel { kNone = 0, kWarning = 1, kCritical = 2 };
const char* alarm_name(AlarmLevel level);

struct ThresholdOutput {
  double flange_mm = 0.0;
  AlarmLevel level = AlarmLevel::kNone;
  bool level_changed = false;
  // Set when a measurement window closes with R_T = d_f - d_rf above max_step_mm.
  std::optional<double> wear_step_mm;
};

class ThresholdStage {
 public:
  explicit ThresholdStage(const ThresholdConfig& config);

  double flange_mm(double clearance_mm) const {
    return config_.flange_nominal_mm - (clearance_mm - config_.sensor_gap_mm);
  }
  // One filtered clearance sample at time t_s (increasing).
  ThresholdOutput step(double t_s, double clearance_mm);

 private:
  AlarmLevel target_level(double clearance_mm) const;

  ThresholdConfig config_;
  double critical_clearance_mm_;
  AlarmLevel level_ = AlarmLevel::kNone;
  std::optional<AlarmLevel> pending_;  // a different level the signal asks for
  double pending_since_s_ = 0.0;
  // Wear-step windows.
  double window_start_s_ = 0.0;
  double window_sum_ = 0.0;
  long window_count_ = 0;
  bool window_open_ = false;
  std::optional<double> previous_window_mm_;
};

}  // namespace flange::host
