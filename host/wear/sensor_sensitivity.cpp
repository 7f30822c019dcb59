// SPDX-License-Identifier: MIT
#include "sensor_sensitivity.h"

namespace flange::host {
namespace {

constexpr double kVoltageStepV = 0.01;  // central difference: the regression is a polynomial
constexpr int kBisections = 50;         // far below a microvolt over a 12 V bracket

}  // namespace

SensitivityAt calibration_sensitivity(const Calibration& calibration, double temp_c) {
  const double v_low = calibration.range.v_min - 1.0;
  const double v_high = calibration.range.v_max + 1.0;
  return [calibration, temp_c, v_low, v_high](double clearance_mm) {
    const auto reads = [&](double v) { return calibration.estimate(v, temp_c).clearance_mm; };
    const bool rising = reads(v_high) > reads(v_low);
    double low = v_low, high = v_high;
    for (int k = 0; k < kBisections; ++k) {
      const double middle = (low + high) / 2.0;
      ((reads(middle) < clearance_mm) == rising ? low : high) = middle;
    }
    const double v = (low + high) / 2.0;
    return (reads(v + kVoltageStepV) - reads(v - kVoltageStepV)) / (2.0 * kVoltageStepV);
  };
}

}  // namespace flange::host
