// SPDX-License-Identifier: MIT
// What the stages find and hand on, below every stage: the gap at each stage of the chain, the
// operating-region cells, the coherences and time segments where the gap lies (locate), and how
// far the picks shrink the held-out gap (verdict).
#pragma once

#include <cstddef>
#include <string>

namespace flange::diagnose {

// The gap at one stage of the chain against what the twin's noise alone gives there.
struct StageGap {
  std::string name;          // "voltage", "clearance", "filtered_clearance", "alarm_timing"
  std::string unit;          // "V", "mm" or "s"
  double gap_rms = 0.0;      // real minus sim (alarm timing: largest onset difference)
  double noise_floor = 0.0;  // the same figure for the noisy twin against the noiseless one
  double real_error_rms = 0.0, sim_error_rms = 0.0;  // clearance stages: against the reference
  // gap_rms > 1.5 x noise_floor (alarm timing: > floor + 1 s, on the held-out part too)
  bool significant = false;
  std::string note;
};

struct RegionCell {
  double clearance_lo = 0, clearance_hi = 0, temp_lo = 0, temp_hi = 0;
  std::size_t n = 0;
  double bias_v = 0, rms_v = 0;
  double bias_lo = 0, bias_hi = 0, rms_lo = 0, rms_hi = 0;  // 95 % block-bootstrap intervals
};

struct InputCoherence {
  std::string input;     // "temperature", "temperature_rate", "clearance"
  double in_band = 0.0;  // mean magnitude-squared coherence over the gap's band (or all bins)
  double peak = 0.0;
  double peak_hz = 0.0;
};

struct TimeSegment {
  double t_start_s = 0, t_end_s = 0, mean_v = 0;
};

// A stretch of the held-out session and the RMS of what the selected effects leave in it.
struct HeldoutWindow {
  double from_s = 0.0, to_s = 0.0;  // held-out t_s of its first and last sample
  double rms_v = 0.0;
};

struct HowFar {
  double rms_before = 0, rms_after = 0, max_before = 0, max_after = 0;  // held-out, V
  double region_rms_before = 0, region_rms_after = 0;                   // in the where-region cell
  std::size_t region_samples = 0;                  // held-out samples in the where-region cell
  double band_rms_before = 0, band_rms_after = 0;  // in the where-band (PSD integrated)
  // The 64th of the held-out samples within the calibration's clearance and temperature ranges
  // where the most is left (diagnosis.cpp, worst_window).
  HeldoutWindow worst_window;
  // The held-out samples within the calibration's clearance and temperature ranges, and the gap's
  // RMS on them before and after the selected effects, V.
  std::size_t within_calibration_samples = 0;
  double within_calibration_rms_before = 0, within_calibration_rms_after = 0;
};

// What the held-out gap that is left is compared with (signatures/vibration.h,
// verdict/verdict_noise.h), and why when it is not the white noise.
struct VerdictNoise {
  double rms_v = 0.0;
  std::string why;
};

}  // namespace flange::diagnose
