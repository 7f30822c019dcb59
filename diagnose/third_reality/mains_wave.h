// SPDX-License-Identifier: MIT
// Pick-up from the mains: 50 or 60 Hz whose frequency sits off nominal and wanders (two slow
// swings of the grid's frequency, integrated into the phase in closed form), with random
// harmonics 2 to 5. The phase runs on absolute time (each session starts wherever the grid is).
// Unit amplitude of the fundamental.
#pragma once

#include <array>

#include "smooth_function.h"
#include "third_random.h"

namespace flange::third_reality {

struct MainsWave {
  double nominal_hz = 50.0;
  double offset_hz = 0.0;  // the grid's mean departure from nominal
  std::array<double, 2> swing_hz{}, swing_period_s{}, swing_phase{};  // the wander
  std::array<double, 4> harmonic{}, harmonic_phase{};                 // 2nd..5th, relative
  double operator()(double absolute_s) const;
};

// A grid standard that shows as a line at `fs_hz` (shows_as_a_line); 0 when neither does.
double usable_mains_hz(double fs_hz, ThirdRandom& random);

MainsWave draw_mains_wave(double nominal_hz, ThirdRandom& random);

void put_mains_wave(const MainsWave& wave, Params& params);
MainsWave get_mains_wave(const Params& params);

}  // namespace flange::third_reality
