// SPDX-License-Identifier: MIT
// IirSampleModel's vector kernel (SampleKernel::kVector, model/iir_sample_model.h): the sections
// side by side in AVX-512 lanes. Internal to the model library.
#pragma once

#include <cstddef>
#include <cstdint>

#include "filter_json.h"

namespace flange::model {
struct SampleResult;
namespace vector {

// Whether this CPU has the instructions and `config` (valid, one channel, no wrap) fits the
// kernel's 32-bit operands and lanes.
bool supported(const CoreConfig& config);

// Filters n samples from `history` (IirSampleModel's layout: 2K + 1 lines of M words, ages
// 1..M), which it leaves as IirCore's load registers after the last sample.
void run(const CoreConfig& config, std::int64_t* history, const std::int32_t* in,
         SampleResult* out, std::size_t n);

}  // namespace vector
}  // namespace flange::model
