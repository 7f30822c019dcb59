// SPDX-License-Identifier: MIT
// Motion in a frequency band: narrow-band random motion (many components with frequencies spread
// normally about a centre, random amplitudes and phases: a resonance driven by broadband forces)
// or one to three tones. Normalised to unit RMS; evaluable at any instant (a jittered logger
// samples between the nominal instants). The components come from a stored seed, so the truth
// holds four numbers, not hundreds.
#pragma once

#include <string>
#include <vector>

#include "smooth_function.h"
#include "third_random.h"

namespace flange::third_reality {

struct BandMotion {
  bool narrow_band = true;
  double centre_hz = 20.0;
  double bandwidth_hz = 0.2;  // narrow band: the spread (standard deviation) of the frequencies
  double seed = 1.0;
  std::vector<double> hz, amplitude, phase;  // the components (set by build())
  void build();
  double operator()(double t_s) const;
};

// Where `f_hz` shows when sampled at `fs_hz`: its alias in [0, fs/2].
double alias_hz(double f_hz, double fs_hz);
// Whether `f_hz` shows at `fs_hz` as a line of its own: its alias at least `margin_hz` from 0 and
// from fs/2.
bool shows_as_a_line(double f_hz, double fs_hz, double margin_hz);

// A centre in 2-45 Hz that shows as a line at `fs_hz` (above its Nyquist frequency, aliased,
// when fs_hz <= 12.5 Hz), narrow band or tones at random.
BandMotion draw_band_motion(double fs_hz, ThirdRandom& random);

void put_band_motion(const BandMotion& motion, Params& params);
BandMotion get_band_motion(const Params& params);

}  // namespace flange::third_reality
