// SPDX-License-Identifier: MIT
// Clearance in millimetres to the filter's Q1.(D-1) sample words and back.
//
// word = round((d - CenterMm) / HalfRangeMm * 2^(D-1)), clipped to the D-bit range. The centre
// 6 mm and half range 8 mm cover -2 to 14 mm: the sensor's 0-10 mm with room for the filter's
// step overshoot. With 16-bit samples one LSB is 8 mm / 32768 = 0.24 um, far below the sensor's
// noise. Every clipped sample is counted.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace flange::host {

struct SampleScaling {
  static constexpr double kCenterMm = 6.0;
  static constexpr double kHalfRangeMm = 8.0;
  int data_bits = 16;

  // 2^(D-1), exactly (a shift: this runs for every sample).
  double full_scale() const { return static_cast<double>(std::int64_t{1} << (data_bits - 1)); }
  // In full-scale units, unclipped: the float engine's input.
  double to_unit(double clearance_mm) const { return (clearance_mm - kCenterMm) / kHalfRangeMm; }
  // The sample word; `clipped` is set when the clearance lies outside the representable range.
  std::int32_t to_word(double clearance_mm, bool& clipped) const {
    const double scaled = std::round(to_unit(clearance_mm) * full_scale());
    const double top = full_scale() - 1.0;
    const double bottom = -full_scale();
    clipped = scaled > top || scaled < bottom;
    return static_cast<std::int32_t>(std::clamp(scaled, bottom, top));
  }
  double unit_to_mm(double unit) const { return kCenterMm + kHalfRangeMm * unit; }
};

}  // namespace flange::host
