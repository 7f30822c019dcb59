// SPDX-License-Identifier: MIT
// The stimuli of `flange diagnose --hw` as the analog signal before the ADC (reals, in LSB of the
// core's D-bit input), together with the words the core receives, so that the diagnosis can
// attribute input rounding like any other fixed-point effect.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace flange::diagnose {

struct HwStimulusSpec {
  std::string kind = "random";  // random | fullscale | sweep | step | impulse | FILE.csv
  std::size_t samples = 10000;  // >= 1 (a FILE gives at most its own rows)
  std::uint64_t seed = 1;       // random and fullscale
  int sample_width = 16;        // D, 2..32
  double fs_hz = 1.0;           // > 0
  double fc_hz = 0.1;           // 0 < fc < fs / 2 (the sweep starts at fc / 20)
};

struct HwStimulus {
  std::vector<double> analog;       // LSB, any real (what the float design sees)
  std::vector<std::int32_t> words;  // model::round_input_sample of each: what the core sees
};

// random: uniform real in [-1/2, 1/2) of full scale; fullscale: uniform in [-1, 1) (the top half
// LSB rounds to the rail); sweep: exponential sine sweep from fc / 20 to 0.49 fs at 0.7 of full
// scale; step: half scale from the first sample; impulse: the largest word, then zeros (these two
// are exact words); FILE.csv: the first column of each line, in LSB, fractional allowed, within
// [-2^(D-1), 2^(D-1) - 1]; lines starting with '#' and a non-numeric first line are skipped.
// Throws InputError (input_error.h), one line naming the option or the file and line.
HwStimulus make_hw_stimulus(const HwStimulusSpec& spec);

}  // namespace flange::diagnose
