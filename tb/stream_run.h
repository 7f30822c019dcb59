// SPDX-License-Identifier: MIT
// Stream mode of the co-simulation runner, for `flange run --engine rtl`: blocks of samples
// arrive on a pipe, go through the Verilated core back to back, are checked against the model,
// and the outputs go back on another pipe.
//
// Protocol (native byte order, both pipes binary):
//   request: uint32 count, then count int32 samples (each in the D-bit range); count 0 ends.
//   reply:   count records of { int32 sample_o, uint8 flags }: flags bit 0 = the model saw a
//            section clip (saturation), bit 1 = RTL and model disagreed (value or latency).
#pragma once

#include <cstdio>
#include <filesystem>

#include "iir_core_dut.h"

namespace flange::tb {

inline constexpr unsigned kStreamSaturated = 1u;
inline constexpr unsigned kStreamMismatch = 2u;

// Serves requests from `in` until a zero count or end of file, every sample on `channel` of the
// core; returns 0, or 2 on a malformed request (a sample out of range) or a channel the set does
// not have.
int serve_stream(const std::filesystem::path& filter_json, Dut& dut, std::FILE* in, std::FILE* out,
                 int channel = 0);

}  // namespace flange::tb
