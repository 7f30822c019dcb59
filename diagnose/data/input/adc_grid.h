// SPDX-License-Identifier: MIT
// The converter grid of a recorded voltage column, estimated from the data alone: any LSB and
// any origin (a converter's range, a level shift and the DAQ software's calibration all move
// it), from the spacing of the values. It tolerates a few values off the grid (glitches) and the
// recording format's 0.5 uV rounding; grids finer than 20 uV cannot be told from that rounding.
#pragma once

#include <optional>
#include <vector>

#include "effect_catalogue.h"

namespace flange::diagnose {

struct AdcGrid {
  double lsb_v = 0.0;          // the step between neighbouring codes
  double lowest_v = 0.0;       // the lowest code used (a grid point: every code is lowest + k lsb)
  double highest_v = 0.0;      // the highest code used
  long codes_used = 0;         // distinct codes in the data
  long codes_spanned = 0;      // codes from the lowest to the highest used
  double share_on_grid = 0.0;  // of all samples, on the grid to within its tolerance
  int bits = 0;  // a converter range that holds every code: 2^bits codes (at least 4 bits)
  // One of the usual ranges (+-10, 0-10, +-5, 0-5 V) whose 2^k grid this is, if any; else a
  // range of 2^bits codes from the lowest used. Always valid for the twin's adc_quantization.
  double v_min = 0.0, v_max = 0.0;
  bool usual_range = false;
  // The LSB over the nearest span / 2^k of a usual converter range (5, 10 or 20 V; 4.096, 10.24
  // or 20.48 V), when that is within kMostCalibrationGain of 1 but not 1: the DAQ software's gain
  // calibration, which scales the codes and so the grid. 1 when no range is that near.
  double calibration_gain = 1.0;

  // The grid point nearest to `volts`.
  double quantise(double volts) const;
  // The twin's adc_quantization effect with this grid.
  sim::EffectSettings as_effect() const;
};

// How far from 1 a gain calibration of the DAQ software goes (its grid is then this far off a
// usual range's); beyond it the grid is taken as a range of its own.
inline constexpr double kMostCalibrationGain = 0.02;

// The grid, when at least 97 % of the samples lie on one with 3 or more codes and an LSB of at
// least 20 uV; nothing for an unquantised column.
std::optional<AdcGrid> estimate_adc_grid(const std::vector<double>& voltage_v);

}  // namespace flange::diagnose
