// SPDX-License-Identifier: MIT
// Bit- and cycle-accurate model of rtl/iir_core.sv: the same arithmetic, flags and timing, so
// that a co-simulation can demand equality of every output word and of the cycle it appears in.
//
// Fixed-point contract (docs/fixed_point.md; the same paragraph heads rtl/iir_core.sv).
// D = SampleWidth, C = CoefWidth, P = AccWidth, F = CoefFracBits, s = FeedbackShift,
// L = SplitShift = C - 1 (17 with 18-bit words: the DSP48E1's P >>> 17), K = NumSections,
// M = SectionOrder.
// - Formats: samples in and out are Q1.(D-1) (Q1.15 by default). Inside the core every signal
//   (each section's input and output, the history) is a (D+s)-bit word, Q1.(D-1+s), D + s <= 25
//   (the DSP48E1 A port): the input enters as x << s and only sample_o is rounded back to D bits.
//   Every coefficient c, b[i] or -a[j], is split into two C-bit ROM words,
//   c = (H + W * 2^-L) * 2^-F with a signed hi word H and a lo word W in [0, 2^L); the
//   error-feedback words E[j] are signed integers (the generator takes E[j] = round(-a[j])).
// - One section k at sample n, u = its input (line k), w = its output history (line k + 1),
//   e = its rounding-error history:
//     lo    = 2^(F-1+L) + sum_i W_b[i] u[n-i] + sum_j W_a[j] w[n-j]
//     acc   = (lo >>> L) + sum_i H_b[i] u[n-i] + sum_j H_a[j] w[n-j] + sum_j E[j] e[n-j]
//     w[n]  = y_ext = saturate_(D+s)(acc >>> F)
//     e[n]  = (acc mod 2^F) - 2^(F-1), the rounding error in accumulator LSBs (F-bit signed)
//   lo and acc are P-bit two's complement and wrap like the DSP48E1 P register (the generator
//   proves that legal samples never make them wrap). Feeding the error back through E shapes
//   the rounding noise by 1 - sum_j E[j] z^-j, which cancels the 1/A(z) gain near z = 1.
// - Rounding: round half up: the preload 2^(F-1+L) becomes 2^(F-1) after the shift. sample_o is
//   rounded from the last section's y_ext: (y_ext + 2^(s-1)) >>> s for s > 0, y_ext for s = 0.
// - Saturation: each y_ext is clipped to [-2^(D-1+s), 2^(D-1+s) - 1] before it enters the
//   history; sample_o to [-2^(D-1), 2^(D-1) - 1]; any clip sets the sticky saturation_o.
// - ROM order: section 0 first; within a section W_b[0..M], W_a[1..M], H_b[0..M], H_a[1..M],
//   E[1..M]: 5M + 2 words. Load registers: K + 1 lines of M + 1 words of D + s bits, newest
//   first (line 0 is x << s, line k + 1 is y_ext of section k), and K error lines of M + 1
//   words (line k: e of section k, F-bit values). The bus target counter (BTC) counts the terms
//   in issue order and addresses each term's ROM word and load register with that one count.
// - Timing: a section issues its T = 5M + 2 terms one per cycle in the order W_b[1..M],
//   W_a[1..M], W_b[0], then H_b[0], H_b[1..M], H_a[1..M], E[1..M]. The first term starts the sum
//   at 2^(F-1+L); H_b[0] is added to P >>> L instead of P. Only W_b[0] and H_b[0] need the
//   previous section's output, so the next section's first 2M terms overlap the MAC's 3 cycles
//   of latency and its W_b[0] waits, if it must, until the cycle after that output is written
//   back. With S = T + max(0, 3 - 2M), section k's last term issues T + kS cycles after the
//   accepted EN and is written back 3 cycles later. From the cycle in which sample_valid_i is
//   accepted to the cycle in which sample_valid_o is high: LatencyCycles = T + (K - 1) * S + 4.
//   A new sample is accepted in the cycle sample_valid_o is high, so CyclesPerSample =
//   LatencyCycles too.
//
// Channels (docs/core.md, "Channels"): NumChannels independent filters share the one MAC. Each
// sample comes with its channel_i; each channel has its own load registers, its own overrun_o and
// saturation_o bit, and, when CoefSets = NumChannels, its own coefficient set (CoefSets = 1: one
// set for all). channel_o names the channel of sample_o. A sample with channel_i >= NumChannels is
// dropped and sets the sticky channel_error_o. The timing above is per accepted sample, whatever
// its channel; a channel's history moves only on its own samples.
//
// Cycle convention: cycle c is the clock period after the c-th rising edge. Inputs given for cycle
// c are sampled at the edge that ends it; registered outputs change at that edge and are seen in
// cycle c + 1. Calls must come in non-decreasing cycle order: pins(c) first, then the inputs of
// cycle c (strobe, clear_flags, reset).
#pragma once

#include <algorithm>
#include <cstdint>
#include <deque>
#include <optional>
#include <vector>

#include "filter_json.h"
#include "iir_mac.h"

namespace flange::model {

// One accepted sample.
struct StepResult {
  std::int32_t sample = 0;         // sample_o, in [-2^(D-1), 2^(D-1) - 1]
  int channel = 0;                 // channel_o: the sample's channel
  bool saturated = false;          // some section clipped while computing it
  std::uint64_t accept_cycle = 0;  // the cycle sample_valid_i was accepted in
  std::uint64_t valid_cycle = 0;   // the cycle sample_valid_o is high: accept_cycle + latency
};

// The outputs of rtl/iir_core.sv in one cycle.
struct Pins {
  std::int32_t sample = 0;  // sample_o (holds the last output; 0 after reset)
  int channel = 0;          // channel_o (sample_o's channel; 0 after reset)
  bool sample_valid = false;
  bool busy = false;
  std::uint32_t overrun = 0;     // overrun_o: bit c for channel c
  std::uint32_t saturation = 0;  // saturation_o: bit c for channel c
  bool channel_error = false;    // channel_error_o
  bool operator==(const Pins&) const = default;
};

class IirCore {
 public:
  // Throws std::invalid_argument when `config` breaks docs/fixed_point.md.
  explicit IirCore(CoreConfig config);

  const CoreConfig& config() const { return config_; }
  int latency_cycles() const { return latency_; }     // accepted EN -> sample_valid_o
  // S: cycles from one section's last term to the next one's (W_b[0] waits for the write-back).
  int section_pitch() const {
    return config_.terms() + std::max(0, kMacLatency - 2 * config_.section_order);
  }
  int cycles_per_sample() const { return latency_; }  // minimum spacing of accepted EN
  int macs_per_sample() const { return config_.rom_depth(); }
  std::int32_t sample_min() const { return sample_min_; }
  std::int32_t sample_max() const { return sample_max_; }
  // Range of y_ext, the extended-precision feedback history: [-2^(D-1+s), 2^(D-1+s) - 1].
  std::int64_t ext_min() const { return ext_min_; }
  std::int64_t ext_max() const { return ext_max_; }

  // The D-bit sample a section passes on for a history word y_ext: (y_ext + 2^(s-1)) >>> s (y_ext
  // when s = 0), saturated to [sample_min(), sample_max()].
  struct Rounded {
    std::int32_t sample = 0;
    bool clipped = false;  // the saturation changed the value
  };
  Rounded round_to_sample(std::int64_t y_ext) const;

  // One sample of `channel` presented at the first cycle the core accepts it (back-to-back
  // streaming). `sample` must lie in [sample_min(), sample_max()] and `channel` in
  // [0, NumChannels) (std::out_of_range otherwise).
  StepResult step(std::int32_t sample, int channel = 0);

  // sample_valid_i high with `sample` and `channel` (channel_i, any value of its ChannelWidth bits)
  // in `cycle`. Returns the result if the core was idle and the channel exists; nothing when it was
  // busy (the sample is dropped and the channel's overrun_o bit rises in cycle + 1) or the channel
  // is out of range (dropped; channel_error_o rises in cycle + 1).
  std::optional<StepResult> strobe(std::uint64_t cycle, std::int32_t sample, int channel = 0);

  // flag_clear_i high in `cycle`: the sticky flags read 0 from cycle + 1, unless a flag event
  // lands at that same edge (the event wins).
  void clear_flags(std::uint64_t cycle);

  // rst_ni low in `cycle`: from cycle + 1 every register is 0 (history, flags, sample_o) and a
  // computation in flight never produces its output. A strobe in the same cycle is ignored.
  void reset(std::uint64_t cycle);

  // The expected outputs in `cycle`.
  Pins pins(std::uint64_t cycle);

  // One channel's load registers as in the RTL: 2K + 1 lines of M + 1 words, newest first; line 0
  // holds x << s, line k + 1 the y_ext history of section k, line K + 1 + k its rounding errors.
  const std::vector<std::int64_t>& lr(int channel = 0) const {
    return lr_.at(static_cast<std::size_t>(channel));
  }
  int channel_width() const { return channel_width_; }  // bits of channel_i and channel_o

 private:
  enum class EventKind {
    kReset, kClear, kBusyStart, kBusyEnd, kSaturation, kOverrun, kChannelError, kOutput
  };
  struct Event {
    std::uint64_t cycle;  // first cycle in which the effect is visible
    EventKind kind;
    std::int32_t value;
    int channel = 0;
  };

  void compute(std::int32_t sample, int channel, StepResult& result, std::vector<bool>& clipped);
  void schedule(const Event& event);
  void advance(std::uint64_t cycle);

  CoreConfig config_;
  int latency_;
  std::int32_t sample_min_, sample_max_;
  std::int64_t ext_min_, ext_max_;
  int channel_width_;
  std::vector<std::vector<std::int64_t>> lr_;  // per channel

  std::uint64_t ready_cycle_ = 0;  // first cycle in which sample_valid_i is accepted
  std::uint64_t now_ = 0;          // last cycle asked about, or the current input cycle
  std::optional<std::uint64_t> reset_cycle_;
  std::deque<Event> events_;  // sorted by cycle, then by kind
  Pins settled_;
  std::uint64_t valid_cycle_ = 0;  // the cycle in which settled_.sample was produced
  bool any_output_ = false;
};

}  // namespace flange::model
