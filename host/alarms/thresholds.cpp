// SPDX-License-Identifier: MIT
#include "thresholds.h"

#include <fmt/format.h>

#include <cmath>

#include "input_error.h"

namespace flange::host {

void validate(const ThresholdConfig& c) {
  auto positive = [](double value, const char* name) {
    if (!std::isfinite(value) || value <= 0.0) {
      throw InputError(fmt::format("threshold {} = {}: must be a finite number > 0", name, value));
    }
  };
  positive(c.flange_nominal_mm, "flange_nominal_mm");
  positive(c.sensor_gap_mm, "sensor_gap_mm");
  positive(c.warning_clearance_mm, "warning_clearance_mm");
  positive(c.critical_flange_mm, "critical_flange_mm");
  positive(c.max_step_mm, "max_step_mm");
  positive(c.step_window_s, "step_window_s");
  if (!std::isfinite(c.hysteresis_mm) || c.hysteresis_mm < 0.0) {
    throw InputError(fmt::format("threshold hysteresis_mm = {}: must be >= 0", c.hysteresis_mm));
  }
  if (!std::isfinite(c.min_dwell_s) || c.min_dwell_s < 0.0) {
    throw InputError(fmt::format("threshold min_dwell_s = {}: must be >= 0", c.min_dwell_s));
  }
  const double critical_clearance = c.flange_nominal_mm - c.critical_flange_mm + c.sensor_gap_mm;
  if (c.warning_clearance_mm <= c.sensor_gap_mm || c.warning_clearance_mm >= critical_clearance) {
    throw InputError(fmt::format(
        "threshold warning_clearance_mm = {}: must lie between the sensor gap {} mm and the "
        "critical clearance {} mm",
        c.warning_clearance_mm, c.sensor_gap_mm, critical_clearance));
  }
}

const char* alarm_name(AlarmLevel level) {
  switch (level) {
    case AlarmLevel::kNone:
      return "none";
    case AlarmLevel::kWarning:
      return "warning";
    case AlarmLevel::kCritical:
      return "critical";
  }
  return "none";
}

ThresholdStage::ThresholdStage(const ThresholdConfig& config)
    : config_(config),
      critical_clearance_mm_(config.flange_nominal_mm - config.critical_flange_mm +
                             config.sensor_gap_mm) {
  validate(config_);
}

AlarmLevel ThresholdStage::target_level(double clearance_mm) const {
  // Raising needs the threshold itself; falling back needs the threshold minus hysteresis, so a
  // signal hovering at a threshold cannot toggle the level.
  const double h = config_.hysteresis_mm;
  if (clearance_mm >= critical_clearance_mm_) return AlarmLevel::kCritical;
  if (level_ == AlarmLevel::kCritical && clearance_mm > critical_clearance_mm_ - h) {
    return AlarmLevel::kCritical;
  }
  if (clearance_mm >= config_.warning_clearance_mm) return AlarmLevel::kWarning;
  if (level_ >= AlarmLevel::kWarning && clearance_mm > config_.warning_clearance_mm - h) {
    return AlarmLevel::kWarning;
  }
  return AlarmLevel::kNone;
}

ThresholdOutput ThresholdStage::step(double t_s, double clearance_mm) {
  ThresholdOutput out;
  out.flange_mm = flange_mm(clearance_mm);
  AlarmLevel wanted = target_level(clearance_mm);
  if (config_.latch_critical && level_ == AlarmLevel::kCritical) wanted = AlarmLevel::kCritical;
  if (wanted == level_) {
    pending_.reset();
  } else {
    // A change must be asked for continuously for min_dwell_s before it happens.
    if (!pending_ || *pending_ != wanted) {
      pending_ = wanted;
      pending_since_s_ = t_s;
    }
    if (t_s - pending_since_s_ >= config_.min_dwell_s) {
      level_ = wanted;
      pending_.reset();
      out.level_changed = true;
    }
  }
  out.level = level_;

  // Eq. 3.37: R_T = d_f - d_rf, d_f this window's mean clearance, d_rf the previous window's.
  // Windows are [start, start + step_window_s): a sample at or past the end closes the window
  // and opens the next.
  if (window_open_ && t_s >= window_start_s_ + config_.step_window_s) {
    const double mean = window_sum_ / static_cast<double>(window_count_);
    if (previous_window_mm_ && mean - *previous_window_mm_ > config_.max_step_mm) {
      out.wear_step_mm = mean - *previous_window_mm_;
    }
    previous_window_mm_ = mean;
    window_open_ = false;
  }
  if (!window_open_) {
    window_open_ = true;
    window_start_s_ = t_s;
    window_sum_ = 0.0;
    window_count_ = 0;
  }
  window_sum_ += clearance_mm;
  ++window_count_;
  return out;
}

}  // namespace flange::host
