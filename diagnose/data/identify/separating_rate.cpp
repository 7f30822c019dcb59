// SPDX-License-Identifier: MIT
#include "separating_rate.h"

#include <algorithm>
#include <cmath>

namespace flange::diagnose {
namespace {

constexpr double kLowestRateHz = 6.0;
constexpr double kHighestRateHz = 100.0;
// Rates in steps of 0.5 Hz: a bench DAQ sets its rate finer than that, and a step of 1 Hz finds
// rates far above the recording's (43 Hz for 50 Hz on a 2 Hz line at 6 Hz, against 21.5 Hz).
constexpr double kRateStepHz = 0.5;

bool separates(double rate_hz, const std::vector<double>& motion_hz,
               const std::vector<double>& mains_harmonics_hz) {
  for (const double mains : mains_harmonics_hz) {
    const double at = folded_hz(mains, rate_hz);
    if (at < kSeparatedLinesHz || at > 0.5 * rate_hz - kSeparatedLinesHz) return false;
    for (const double motion : motion_hz) {
      if (std::abs(folded_hz(motion, rate_hz) - at) < kSeparatedLinesHz) return false;
    }
  }
  return true;
}

}  // namespace

double folded_hz(double f_hz, double fs_hz) {
  const double folded = std::fmod(std::abs(f_hz), fs_hz);
  return std::min(folded, fs_hz - folded);
}

std::vector<double> motion_folding_onto(double line_hz, double fs_hz,
                                        const std::vector<double>& mains_harmonics_hz) {
  std::vector<double> out;
  for (int k = 0; k * fs_hz - line_hz <= kHighestMotionHz; ++k) {
    for (const double f : {k * fs_hz - line_hz, k * fs_hz + line_hz}) {
      if (f <= 0.0 || f > kHighestMotionHz) continue;
      const bool at_the_mains =
          std::any_of(mains_harmonics_hz.begin(), mains_harmonics_hz.end(),
                      [&](double m) { return std::abs(f - m) < kSeparatedLinesHz; });
      if (!at_the_mains && std::find(out.begin(), out.end(), f) == out.end()) out.push_back(f);
    }
  }
  return out;
}

std::optional<double> separating_rate_hz(double line_hz, double fs_hz,
                                         const std::vector<double>& mains_harmonics_hz) {
  if (mains_harmonics_hz.empty()) return std::nullopt;
  const std::vector<double> motion = motion_folding_onto(line_hz, fs_hz, mains_harmonics_hz);
  std::vector<double> rates;
  for (double rate = kLowestRateHz; rate <= kHighestRateHz; rate += kRateStepHz) rates.push_back(rate);
  std::stable_sort(rates.begin(), rates.end(), [&](double a, double b) {
    return std::abs(a - fs_hz) < std::abs(b - fs_hz);
  });
  for (const double rate : rates) {
    if (std::abs(rate - fs_hz) < 0.5) continue;  // the recording's own rate
    if (separates(rate, motion, mains_harmonics_hz)) return rate;
  }
  return std::nullopt;
}

}  // namespace flange::diagnose
