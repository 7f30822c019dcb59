// SPDX-License-Identifier: MIT
// IirSampleModel's vector kernels (SampleKernel::kVector and kVectorMerged,
// model/iir_sample_model.h), internal to the model library. x86-64 with AVX-512 only, chosen at run
// time (the rest of the library is built for the baseline ISA).
//
// The sections run side by side in 64-bit SIMD lanes (4 lanes for K <= 4, 8 for K <= 8), section
// k on sample n - 2k: its input, section k-1's y_ext, was made two steps earlier, so the lane
// shift (valignq) is not on the loop-carried path, which is each section's own feedback only.
// Every signal is kept biased to be non-negative (u and w plus 2^(D-1+s), the error as
// r = e + 2^(F-1), negated within F bits where E[1] < 0), the biases' constants folded into one
// preload per lane, so that products of non-negative operands are exact and the sums need no sign
// extension on the loop-carried path. Two ways to sum, both exact:
// - Sums::kSplit (kVector, AVX-512F/VL/IFMA): the contract's two phases, lo (W words) and hi
//   (H and E words), by 52-bit multiply-adds (vpmadd52luq), the older hi terms modulo 2^52 and
//   sign-extended; acc = hi + (lo >>> L). Loop-carried: y -> W_a[1] w multiply-add -> >>> L ->
//   add -> y, 7 cycles of latency a step.
// - Sums::kMerged (kVectorMerged, AVX-512F/VL/DQ): kMerged's one sum with c = H 2^L + W and
//   E 2^L, by 64-bit products (vpmullq); y_ext = sum >>> (L + F), r = (sum >>> L) mod 2^F.
//   Half the products, and 6 cycles of latency a step where vpmullq is one 3-cycle micro-op (AMD
//   Zen 4 on); on Intel it is three of 15 cycles, so kAuto takes it only on AMD
//   (merged_preferred). Measured, a step takes about 11 cycles on an AMD host, the split sums'
//   about 13 (docs/benchmarks_core.md).
// A chunk of steps first runs without the clip test, only tracking y_ext's range; if some y_ext
// left [-2^(D-1+s), 2^(D-1+s) - 1] the chunk is run again from its start with the test and the
// clips.
// The last section's y_ext is rounded and clipped per chunk.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "filter_json.h"

namespace flange::model {
struct SampleResult;
namespace vector {

enum class Sums { kSplit, kMerged };

// Whether this CPU has the instructions for `sums` and `config` fits the kernel: one channel,
// M <= 2, 2 <= K <= 8, D + s <= 31, F <= 31, and every sum of biased values within its bound. The
// model adds that no legal input can make the contract's lo or acc wrap.
bool supported(const CoreConfig& config, Sums sums);

// Whether this CPU runs Sums::kMerged faster than Sums::kSplit (see above).
bool merged_preferred();

// The words laid out per lane, and the constants; built once per model.
struct Plan {
  Sums sums = Sums::kSplit;
  int lanes = 0, order = 0, sections = 0;
  int split = 0, frac = 0, shift = 0;  // L, F, s
  std::int64_t half_f = 0, mask_f = 0, ext_min = 0, ext_max = 0, half_s = 0, out_max = 0;
  std::int64_t bias = 0;    // Y = 2^(D-1+s): every signal in the lanes is kept as value + Y >= 0
  bool signed_ha1 = false;  // some section's H_a[1] is negative
  // Per word kind (W_b[0..M], W_a[1..M], H_b[0..M], H_a[1..M], E[1..M]), `lanes` values.
  std::vector<std::int64_t> words;
};
Plan make_plan(const CoreConfig& config, Sums sums);  // config must be supported

// Filters n samples from `history` (IirSampleModel's layout: 2K + 1 lines of M words, ages
// 1..M), which it leaves as IirCore's load registers after the last sample.
void run(const Plan& plan, std::int64_t* history, const std::int32_t* in, SampleResult* out,
         std::size_t n);

}  // namespace vector
}  // namespace flange::model
