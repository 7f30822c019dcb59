// SPDX-License-Identifier: MIT
// The sample-level twin of the cycle model (model/iir_core.h): the same arithmetic on every
// accepted sample, with no clock cycles, pins or events, for callers that want only the samples.
//
// It computes exactly what IirCore::step returns in StepResult::sample and ::saturated, under the
// fixed-point contract of model/iir_core.h (docs/fixed_point.md): the same ROM words, the P-bit
// accumulator preloaded with 2^(Fa-1) and wrapping like the DSP48E1 P register, y_ext = acc >>> Fa
// clipped to D + s bits and fed back as it is, y rounded half up from y_ext and clipped to D bits,
// the per-sample saturation flag set by either clip in any section. Only the bookkeeping differs.
// In place of the load registers each section keeps M partial sums (transposed direct form): z[j]
// holds, modulo 2^64, every product of the samples so far that belongs to the sum of sample n+1+j
// (z[0] with the rounding constant). The products are the core's, b[i] times the D-bit operand
// (line k rounded to D bits is, bit for bit, section k - 1's clipped output) and -a[j] times
// y_ext; a sum modulo 2^64 depends neither on the order nor on the grouping of its terms, so
// b[0] x[n] + z[0] has the low P bits of the core's accumulator, wrapped or not. The cycle model
// stays the specification of the RTL; tests/model/iir_sample_model_test.cpp proves the two equal
// on every checked-in set, on random legal configurations and on an accumulator that wraps.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "filter_json.h"

namespace flange::model {

// One output sample: what IirCore::step reports in StepResult::sample and ::saturated.
struct SampleResult {
  std::int32_t sample = 0;  // sample_o, in [-2^(D-1), 2^(D-1) - 1]
  bool saturated = false;   // some section clipped while computing it (not sticky)
  bool operator==(const SampleResult&) const = default;
};

class IirSampleModel {
 public:
  // Throws std::invalid_argument when `config` breaks docs/fixed_point.md (as IirCore does) or has
  // more than one channel (IirSampleBank serves those, one IirSampleModel per channel).
  explicit IirSampleModel(CoreConfig config);

  const CoreConfig& config() const { return config_; }
  std::int32_t sample_min() const { return sample_min_; }
  std::int32_t sample_max() const { return sample_max_; }
  // Whether some legal input could make a section's P-bit sum wrap: |sum| bounded by
  // 2^(Fa-1) + sum|B| 2^(D-1) + sum|A| 2^(D-1+s) does not fit P - 1 bits. The generator refuses
  // such sets (docs/fixed_point.md), so for generated sets this is false and the wrap, which
  // would change nothing, is skipped; hand-made configurations still get it.
  bool accumulator_can_wrap() const { return can_wrap_; }

  // One sample, as IirCore::step. `sample` must lie in [sample_min(), sample_max()]
  // (std::out_of_range otherwise, and the state is left as it was).
  SampleResult step(std::int32_t sample);

  // in.size() samples in order, continuing from the previous call; out[i] is in[i]'s result.
  // out.size() must equal in.size() (std::invalid_argument); every input must lie in
  // [sample_min(), sample_max()] (std::out_of_range, thrown before any sample is filtered).
  void filter(std::span<const std::int32_t> in, std::span<SampleResult> out);

  // Every history word to 0, as after the core's reset.
  void reset();

 private:
  using Kernel = void (IirSampleModel::*)(const std::int32_t* in, SampleResult* out, std::size_t n);
  // kOrder, kSections: M and K when known at compile time (the words and partial sums then live
  // in local arrays the compiler keeps in registers), 0 to read them from config_.
  template <int kOrder, int kSections, bool kWrap>
  void run(const std::int32_t* in, SampleResult* out, std::size_t n);
  template <bool kWrap>
  static Kernel biquad_kernel(int sections);
  Kernel choose_kernel() const;

  CoreConfig config_;
  std::int32_t sample_min_, sample_max_;
  std::int64_t ext_min_, ext_max_;
  bool can_wrap_;
  Kernel kernel_;
  // Per section, M partial sums z[0..M-1] (two's complement bits modulo 2^64).
  std::vector<std::uint64_t> partial_;
};

}  // namespace flange::model
