// SPDX-License-Identifier: MIT
// IirSampleModel's vector kernel (SampleKernel::kVector, model/iir_sample_model.h), internal to the
// model library. x86-64 with AVX-512F, VL and IFMA only, chosen at run time (the rest of the
// library is built for the baseline ISA).
//
// The sections run side by side in 64-bit SIMD lanes (4 lanes for K <= 4, 8 for K <= 8), section
// k on sample n - 2k: its input, section k-1's y_ext, was made two steps earlier, so the lane
// shift (valignq) is not on the loop-carried path, which is each section's own feedback only.
// Per step and lane: the H and E terms of the last step's y_ext and error (w[n-1], r[n-1]) are
// exact 32 x 32-bit products (vpmuldq) on exact int64 sums; all other terms, lo's W_a[1] w[n-1]
// included, are summed modulo 2^52 by multiply-adds (vpmadd52luq) and sign-extended from bit 51,
// which `supported` and the model's bounds make exact for every legal input (|lo|, |acc| < 2^51;
// y_ext, r and the words within 32 bits). The loop-carried path is 9 cycles a step (acc -> r ->
// E[1] r product -> two adds -> acc; y -> W_a[1] w multiply-add -> shifts -> add -> y). The error
// history is kept as r = acc mod 2^F, its constant -2^(F-1) E folded into lo's preload. A chunk of
// steps first runs without the clip test, only tracking y_ext's range; if some y_ext left
// [-2^(D-1+s), 2^(D-1+s) - 1] the chunk is run again from its start with the test and the clips.
// The last section's y_ext is rounded and clipped per chunk.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "filter_json.h"

namespace flange::model {
struct SampleResult;
namespace vector {

// Whether this CPU has the instructions and `config`'s shape fits the kernel: one channel, M <= 2,
// 2 <= K <= 8, D + s <= 32, F <= 31. The model adds the value bounds (no P-bit wrap; |lo|, |acc|
// below 2^51 for every legal input).
bool supported(const CoreConfig& config);

// The words laid out per lane, and the constants; built once per model.
struct Plan {
  int lanes = 0, order = 0, sections = 0;
  int split = 0, frac = 0, shift = 0;  // L, F, s
  std::int64_t pre_lo = 0, half_f = 0, mask_f = 0, ext_min = 0, ext_max = 0, half_s = 0,
               out_max = 0;
  // Per word kind (W_b[0..M], W_a[1..M], H_b[0..M], H_a[1..M], E[1..M]), `lanes` values.
  std::vector<std::int64_t> words;
};
Plan make_plan(const CoreConfig& config);  // config must be supported

// Filters n samples from `history` (IirSampleModel's layout: 2K + 1 lines of M words, ages
// 1..M), which it leaves as IirCore's load registers after the last sample.
void run(const Plan& plan, std::int64_t* history, const std::int32_t* in, SampleResult* out,
         std::size_t n);

}  // namespace vector
}  // namespace flange::model
