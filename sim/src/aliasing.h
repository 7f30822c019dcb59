// SPDX-License-Identifier: MIT
// Where a tone lands after sampling: the frequency a DFT of the samples shows.
#pragma once

namespace flange::sim {

// The apparent frequency in [0, fs/2] of a tone at `frequency_hz` (>= 0) sampled at
// `sample_rate_hz` (> 0): its distance to the nearest multiple of the sample rate.
// E.g. 50 Hz at 6 Hz -> 2 Hz; 150 Hz at 6 Hz -> 0 Hz (DC); 51 Hz at 100 Hz -> 49 Hz.
double alias_frequency_hz(double frequency_hz, double sample_rate_hz);

}  // namespace flange::sim
