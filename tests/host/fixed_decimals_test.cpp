// SPDX-License-Identifier: MIT
// Six-decimal output: the inline rounding is std::llround's, ties and all.
#include "fixed_decimals.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

namespace flange::host {
namespace {

TEST(FixedDecimals, RoundingIsLlroundsTiesAndNeighboursIncluded) {
  std::vector<double> values = {0.0, -0.0, 0.5, -0.5, 1.5, -1.5, 2.5, -2.5, 0.49999999999999994,
                                -0.49999999999999994, 0x1p52 - 0.5, -(0x1p52 - 0.5), 0x1p52,
                                0x1p53 + 2, -0x1p60, 4503599627370495.5};
  std::mt19937_64 random(7);
  for (int k = 0; k < 200000; ++k) {
    const double tie = static_cast<double>(static_cast<long long>(random() % 2000000000)) + 0.5;
    for (const double x : {tie, -tie}) {
      values.push_back(x);
      values.push_back(std::nextafter(x, 0.0));
      values.push_back(std::nextafter(x, 2 * x));
    }
    // Any magnitude up to about 2^63.
    values.push_back(std::ldexp(std::uniform_real_distribution<double>(-1.0, 1.0)(random),
                                static_cast<int>(random() % 63)));
  }
  for (const double x : values) EXPECT_EQ(round_half_away(x), std::llround(x)) << x;
}

TEST(FixedDecimals, WritesSixDecimalsAsTheCountOfMillionthsSays) {
  EXPECT_EQ(fixed6(0.0), "0.000000");
  EXPECT_EQ(fixed6(-0.0000004), "0.000000");
  EXPECT_EQ(fixed6(-0.0000006), "-0.000001");
  EXPECT_EQ(fixed6(166666.5), "166666.500000");
  EXPECT_EQ(fixed6(-1.23456789), "-1.234568");
  EXPECT_EQ(fixed6(25.0000005), "25.000001");
  EXPECT_EQ(fixed6(9.9999996), "10.000000");
  EXPECT_EQ(fixed6(-99.9999996), "-100.000000");
  EXPECT_EQ(fixed6(123456789.0123456), "123456789.012346");
  EXPECT_EQ(fixed6(0.0000505), "0.000051");
  // Every length of the whole part, at both ends (1 to 8 digits by pairs, then std::to_chars;
  // x 1e6 stays exact up to 9 digits).
  for (unsigned long long whole = 1, digits = 1; digits <= 9; whole *= 10, ++digits) {
    const std::string first = std::to_string(whole), last = std::to_string(whole * 10 - 1);
    EXPECT_EQ(fixed6(static_cast<double>(whole)), first + ".000000") << digits;
    EXPECT_EQ(fixed6(-static_cast<double>(whole * 10 - 1) - 0.25), "-" + last + ".250000")
        << digits;
  }
  // Against the plain way (std::llround, then the whole part and the decimals through
  // std::to_chars), over integer parts of 1 to 13 digits.
  std::mt19937_64 random(11);
  for (int k = 0; k < 200000; ++k) {
    const double x = std::ldexp(std::uniform_real_distribution<double>(-1.0, 1.0)(random),
                                static_cast<int>(random() % 43));
    const long long millionths = std::llround(x * 1e6);
    const unsigned long long magnitude =
        millionths < 0 ? 0ULL - static_cast<unsigned long long>(millionths)
                       : static_cast<unsigned long long>(millionths);
    char decimals[8];
    std::snprintf(decimals, sizeof decimals, "%06llu", magnitude % 1000000);
    const std::string expected = (millionths < 0 ? "-" : "") +
                                 std::to_string(magnitude / 1000000) + "." + decimals;
    EXPECT_EQ(fixed6(x), expected) << x;
  }
}

}  // namespace
}  // namespace flange::host
