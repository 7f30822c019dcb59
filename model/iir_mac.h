// SPDX-License-Identifier: MIT
// The arithmetic of rtl/iir_mac.sv: exact products, an accumulator that wraps at its width.
#pragma once

#include <cstdint>

namespace flange::model {

// Pipeline registers between an operand pair and its sum in P (A/B, M, P), as in the RTL.
inline constexpr int kMacLatency = 3;

// The two's complement value of the low `width` bits of `bits` (1 <= width <= 64): what a
// `width`-bit register holds after a sum that may have wrapped.
constexpr std::int64_t wrap_to_width(std::uint64_t bits, int width) {
  if (width >= 64) return static_cast<std::int64_t>(bits);
  const std::uint64_t sign = std::uint64_t{1} << (width - 1);
  const std::uint64_t low = bits & ((sign << 1) - 1);
  return static_cast<std::int64_t>(low ^ sign) - static_cast<std::int64_t>(sign);
}

// One accumulation step, P <= P + A * B, modulo 2^64 (wrap_to_width reduces it further). The
// product itself is exact: |A| < 2^25 and |B| < 2^32 in every legal set.
constexpr std::uint64_t mac(std::uint64_t p, std::int64_t a, std::int64_t b) {
  return p + static_cast<std::uint64_t>(a * b);
}

}  // namespace flange::model
