// SPDX-License-Identifier: MIT
// Test signals for the core, in integer sample units (Q1.(D-1)), and the cycle schedules that
// present them to the RTL and the model alike.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace flange::tb {

// What a signal generator needs to know about the core and the filter.
struct SignalSpec {
  int sample_width = 16;  // D, 2..32
  double fs_hz = 1.0;     // sample rate, > 0
  double fc_hz = 0.1;     // cut-off, 0 < fc < fs / 2
};

std::int32_t full_scale_max(int sample_width);  // 2^(D-1) - 1
std::int32_t full_scale_min(int sample_width);  // -2^(D-1)

// Full-scale impulse (max) followed by zeros; n >= 1.
std::vector<std::int32_t> impulse(const SignalSpec& spec, std::size_t n);
// Step to `level` (fraction of full scale, -1 <= level < 1) from the first sample on.
std::vector<std::int32_t> step(const SignalSpec& spec, std::size_t n, double level);
// Full-scale square wave between min and max, half period `half_period` >= 1 samples.
std::vector<std::int32_t> square(const SignalSpec& spec, std::size_t n, std::size_t half_period);
// Logarithmic sine sweep from f0 to f1 Hz (0 < f0 < f1 <= fs / 2) at `level` of full scale.
// The phase (rad) at time t of an exponential chirp from f0 to f1 Hz over `duration` s:
// 2 pi f0 T / k (e^(k t / T) - 1) with k = ln(f1 / f0).
double exponential_chirp_phase(double f0, double f1, double duration, double t);
std::vector<std::int32_t> sine_sweep(const SignalSpec& spec, std::size_t n, double f0, double f1,
                                     double level);
// Independent uniform samples in [level * min, level * max] (0 < level <= 1), seeded.
std::vector<std::int32_t> uniform_random(const SignalSpec& spec, std::size_t n, double level,
                                         std::uint64_t seed);

// One input event for a cycle of the core.
struct Action {
  enum class Kind { kReset, kStrobe, kClear };
  std::uint64_t cycle = 0;
  Kind kind = Kind::kStrobe;
  std::int32_t sample = 0;  // for kStrobe
  int channel = 0;          // for kStrobe: channel_i
};

// A schedule of actions, sorted by cycle (several kinds may share a cycle).
struct Stimulus {
  std::vector<Action> actions;
  void add(const Action& action);  // keeps the order
  std::uint64_t last_cycle() const;
};

// Each sample strobed `spacing` cycles after the previous one, from `first_cycle` on. With
// spacing = cycles per sample this is back-to-back streaming; less makes overruns.
Stimulus every(const std::vector<std::int32_t>& samples, std::uint64_t spacing,
               std::uint64_t first_cycle = 1);

}  // namespace flange::tb
