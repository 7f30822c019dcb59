// SPDX-License-Identifier: MIT
// What the board's display must show for a Q1.15 word (docs/board.md, "Display arithmetic").
#pragma once

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>

namespace flange::tb::board {

// What the display must show for a Q1.15 word: mm = 6 + 8 word / 2^15 to two decimals, rounded
// half up; computed in double (every value involved is exact in binary), independently of the
// RTL's integer formula.
inline std::string expected_display(std::int16_t word) {
  const double hundredths = std::floor(100.0 * (6.0 + 8.0 * word / 32768.0) + 0.5);
  const long h = static_cast<long>(hundredths);
  const long mag = std::labs(h);
  std::string text;
  if (h < 0) {
    text = "-";
  } else if (mag >= 1000) {
    text = std::to_string(mag / 1000);
  } else {
    text = " ";
  }
  text += std::to_string((mag / 100) % 10) + "." + std::to_string((mag / 10) % 10) +
          std::to_string(mag % 10);
  return text;
}

}  // namespace flange::tb::board
