// SPDX-License-Identifier: MIT
// The sample-level twin of the cycle model (model/iir_core.h): the same arithmetic on every
// accepted sample, with no clock cycles, pins or events, for callers that want only the samples.
//
// It computes exactly what IirCore::step returns in StepResult::sample and ::saturated, under the
// fixed-point contract v2 of model/iir_core.h (docs/fixed_point.md): per section, with u its
// (D+s)-bit input, w its y_ext history and e its rounding-error history,
//   lo    = 2^(F-1+L) + sum W_b[i] u[n-i] + sum W_a[j] w[n-j]              (P bits, wraps)
//   acc   = (lo >>> L) + sum H_b[i] u[n-i] + sum H_a[j] w[n-j] + sum E[j] e[n-j]  (P bits, wraps)
//   y_ext = clip_(D+s)(acc >>> F),  e[n] = (acc mod 2^F) - 2^(F-1),
// section 0's u is x << s, section k's is section k-1's y_ext, and the output is the last y_ext
// rounded half up to D bits and clipped; the per-sample saturation flag is set by any clip.
// The state is the core's load registers (every line's last M words, errors included), so every
// kernel below continues from where any other stopped. Only the bookkeeping differs from IirCore:
// - kTwoPhase: the contract as written, lo and acc wrapped to P bits; for any legal config.
// - kMerged: when no legal input can make lo or acc wrap, floor((X + 2^L H) / 2^L) =
//   floor(X / 2^L) + H merges the phases into one sum with c = H 2^L + W (and E 2^L for the
//   error terms): acc = (2^(F-1+L) + sum c_b u + sum c_a w + sum E 2^L e) >>> L. Used when every
//   such sum also fits int64 (|c| < 2^34 and |u| < 2^24 for the generator's biquads).
// - kVector (x86-64 with AVX-512F, VL and IFMA only, chosen at run time): no wrap, every signal
//   within 31 bits and at most 8 sections of order 1 or 2; the sections run side by side in SIMD
//   lanes, section k on sample n - 2k (model/iir_sample_vector.h), the two phases' sums by exact
//   52-bit multiply-adds of biased, non-negative operands.
// - kVectorMerged (AVX-512F, VL and DQ): the same lanes with kMerged's one sum per section, one
//   64-bit product per term. kAuto takes it before kVector on AMD, whose cores multiply 64-bit
//   words in one short micro-op (vector::merged_preferred).
// tests/model/iir_sample_model_test.cpp proves every kernel equal to IirCore on every checked-in
// set, on random legal configurations and on an accumulator that wraps.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "filter_json.h"

namespace flange::model {

namespace vector {
struct Plan;
}

// One output sample: what IirCore::step reports in StepResult::sample and ::saturated.
struct SampleResult {
  std::int32_t sample = 0;  // sample_o, in [-2^(D-1), 2^(D-1) - 1]
  bool saturated = false;   // some section clipped while computing it (not sticky)
  bool operator==(const SampleResult&) const = default;
};

// How IirSampleModel computes (see the header comment); kAuto takes the fastest that applies.
enum class SampleKernel { kAuto, kTwoPhase, kMerged, kVector, kVectorMerged };
const char* to_string(SampleKernel kernel);

class IirSampleModel {
 public:
  // Throws std::invalid_argument when `config` breaks docs/fixed_point.md (as IirCore does), has
  // more than one channel (IirSampleBank serves those, one IirSampleModel per channel), or when
  // `kernel` is not kAuto and cannot compute `config` exactly on this machine (kernel_available).
  explicit IirSampleModel(CoreConfig config, SampleKernel kernel = SampleKernel::kAuto);

  // Whether `kernel` can compute `config` (a valid one-channel config) exactly on this machine.
  static bool kernel_available(const CoreConfig& config, SampleKernel kernel);

  const CoreConfig& config() const { return config_; }
  SampleKernel kernel() const { return kernel_; }  // never kAuto
  std::int32_t sample_min() const { return sample_min_; }
  std::int32_t sample_max() const { return sample_max_; }
  // Whether some legal input could make a section's lo or acc wrap at P bits: with every u and w
  // within D + s bits and every e within F bits, the sum of the terms' largest magnitudes does not
  // fit P - 1 bits. The generator refuses such sets (docs/fixed_point.md), so for generated sets
  // this is false; hand-made configurations that wrap run the two-phase kernel.
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
  struct Limits;  // what the kernels share, filled from config_
  template <int kOrder, int kSections>
  void run_merged(const std::int32_t* in, SampleResult* out, std::size_t n);
  void run_two_phase(const std::int32_t* in, SampleResult* out, std::size_t n);
  void run_vector(const std::int32_t* in, SampleResult* out, std::size_t n);
  void run(const std::int32_t* in, SampleResult* out, std::size_t n);

  CoreConfig config_;
  SampleKernel kernel_;
  std::int32_t sample_min_, sample_max_;
  std::int64_t ext_min_, ext_max_;
  bool can_wrap_;
  using MergedRun = void (IirSampleModel::*)(const std::int32_t*, SampleResult*, std::size_t);
  MergedRun merged_run_ = nullptr;
  // Per section the merged words c_b[0..M], c_a[1..M], E[1..M] 2^L (kMerged), 3M + 1 of them.
  std::vector<std::int64_t> merged_;
  std::shared_ptr<const vector::Plan> plan_;  // kVector: the words in lanes
  // The load registers without the newest word: line l (0..K: inputs and y_ext, K+1..2K: errors)
  // holds its words of ages 1..M at [l M, l M + M).
  std::vector<std::int64_t> history_;
};

}  // namespace flange::model
