// SPDX-License-Identifier: MIT
// Numbers with six decimals for the output CSVs, written the same way by every command (flange run
// and flange stream print the same clearance identically, ties included).
#pragma once

#include <array>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <string>

namespace flange::host {

// The most characters write_fixed6 writes: a sign, the integer part (a count of millionths is at
// most 2^63, so at most 13 digits), the point and six decimals.
inline constexpr int kMaxFixed6IntegerDigits = 13;
inline constexpr std::size_t kMaxFixed6Chars = 1 + kMaxFixed6IntegerDigits + 1 + 6;

namespace detail {
// "00" "01" ... "99": two decimal digits per lookup.
inline constexpr std::array<char, 200> kDigitPairs = [] {
  std::array<char, 200> pairs{};
  for (int i = 0; i < 100; ++i) {
    pairs[static_cast<std::size_t>(2 * i)] = static_cast<char>('0' + i / 10);
    pairs[static_cast<std::size_t>(2 * i + 1)] = static_cast<char>('0' + i % 10);
  }
  return pairs;
}();
}  // namespace detail

// std::llround(x), ties away from zero, inline: the library call was a tenth of `flange run`'s
// output time. Below 2^52 the truncated part and the rest are exact, so the halves compare
// exactly; beyond (and for NaN) the library decides.
inline long long round_half_away(double x) {
  if (!(std::abs(x) < 0x1p52)) return std::llround(x);
  const auto whole = static_cast<long long>(x);  // toward zero
  const double rest = x - static_cast<double>(whole);
  return whole + (rest >= 0.5 ? 1 : 0) - (rest <= -0.5 ? 1 : 0);
}

// Writes `value` with six decimals at `at`, which has room for kMaxFixed6Chars, and returns the
// end. Through an integer count of millionths: several times faster than formatting the double
// at a fixed precision, and the same digits away from exact ties.
inline char* write_fixed6(char* at, double value) {
  const long long millionths = round_half_away(value * 1e6);
  // The magnitude in unsigned arithmetic, where negating the most negative count is defined.
  const unsigned long long magnitude = millionths < 0
                                           ? 0ULL - static_cast<unsigned long long>(millionths)
                                           : static_cast<unsigned long long>(millionths);
  if (millionths < 0) *at++ = '-';
  // Clearances, temperatures and voltages have one or two digits before the point: a lookup;
  // times up to eight digits (three years in seconds) by pairs from the right.
  const unsigned long long whole = magnitude / 1000000;
  if (whole < 10) {
    *at++ = static_cast<char>('0' + whole);
  } else if (whole < 100) {
    std::memcpy(at, &detail::kDigitPairs[2 * whole], 2);
    at += 2;
  } else if (whole < 100000000) {
    auto rest = static_cast<unsigned>(whole);
    const int digits = rest < 1000       ? 3
                       : rest < 10000    ? 4
                       : rest < 100000   ? 5
                       : rest < 1000000  ? 6
                       : rest < 10000000 ? 7
                                         : 8;
    char* p = at + digits;
    for (; rest >= 100; rest /= 100) {
      p -= 2;
      std::memcpy(p, &detail::kDigitPairs[2 * (rest % 100)], 2);
    }
    if (rest >= 10) {
      std::memcpy(p - 2, &detail::kDigitPairs[2 * rest], 2);
    } else {
      p[-1] = static_cast<char>('0' + rest);
    }
    at += digits;
  } else {
    at = std::to_chars(at, at + kMaxFixed6IntegerDigits, whole).ptr;
  }
  *at++ = '.';
  // The six decimals as three pairs, each computed apart (no chain of divisions).
  const auto fraction = static_cast<unsigned>(magnitude % 1000000);
  const unsigned low_four = fraction % 10000;
  std::memcpy(at, &detail::kDigitPairs[2 * (fraction / 10000)], 2);
  std::memcpy(at + 2, &detail::kDigitPairs[2 * (low_four / 100)], 2);
  std::memcpy(at + 4, &detail::kDigitPairs[2 * (low_four % 100)], 2);
  return at + 6;
}

inline std::string fixed6(double value) {
  char text[kMaxFixed6Chars];
  return std::string(text, write_fixed6(text, value));
}

}  // namespace flange::host
