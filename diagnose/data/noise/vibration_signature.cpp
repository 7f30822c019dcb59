// SPDX-License-Identifier: MIT
#include "vibration_signature.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "criteria.h"
#include "recording_series.h"
#include "series_statistics.h"

namespace flange::diagnose {
namespace {

// Samples on each side of the centred moving mean the level signature takes off the gap: about
// 8 s at 6 Hz, so what a bias leaves (slow: the micrometer and the heating take minutes) is
// removed and motion aliased down to a few tenths of a hertz stays.
constexpr std::size_t kLevelHalfWindow = 24;

// Fits E[y] = a + b s2 by least squares and fills the signature's statistics; `per_motion`
// converts b to the motion's variance in mm^2 (1/2 for squared differences, 1 for levels).
VibrationSignature regress_on_sensitivity(const std::vector<double>& y,
                                          const std::vector<double>& s2, double per_motion) {
  VibrationSignature signature;
  if (y.size() < 16) return signature;
  const LineFit fit = line_fit(s2, y);
  if (!fit.fitted) return signature;
  signature.slope_t = fit.slope_t;
  signature.rms_mm = std::sqrt(std::max(0.0, fit.slope) * per_motion);
  signature.voltage_noise_std_v = std::sqrt(std::max(0.0, fit.intercept) * per_motion);
  const double motion_share = fit.slope * mean_of(s2) / std::max(mean_of(y), 1e-30);
  signature.present =
      signature.slope_t > criteria::kMotionSlopeT && motion_share > criteria::kMotionLeastShare;
  return signature;
}

}  // namespace

VibrationSignature vibration_signature(const std::vector<double>& gap_v,
                                       const std::vector<double>& sensitivity_v_per_mm,
                                       const std::vector<double>& clearance_mm) {
  const std::size_t n = gap_v.size();
  if (n < 2 * kLevelHalfWindow + 16) return {};
  const std::vector<bool> rest = pairs_at_rest(clearance_mm);
  const auto resting = [&](std::size_t pair) { return rest.empty() || rest[pair]; };
  // Squared first differences: motion white at fs.
  std::vector<double> diff_sq, diff_s2;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    if (!resting(i)) continue;
    diff_sq.push_back(std::pow(gap_v[i + 1] - gap_v[i], 2));
    diff_s2.push_back(std::pow(0.5 * (sensitivity_v_per_mm[i] + sensitivity_v_per_mm[i + 1]), 2));
  }
  const VibrationSignature by_differences = regress_on_sensitivity(diff_sq, diff_s2, 0.5);
  // Squared levels about a centred moving mean: motion whose aliases fall low in the band
  // (a narrow resonance, sparse impacts), which differences pass only weakly. At rest, only
  // windows without a move count.
  const std::size_t w = kLevelHalfWindow;
  std::vector<std::size_t> moves_before(n, 0);  // moving pairs among 0 .. i-1
  for (std::size_t i = 1; i < n; ++i) {
    moves_before[i] = moves_before[i - 1] + (resting(i - 1) ? 0 : 1);
  }
  std::vector<double> level_sq, level_s2;
  double sum = 0.0;
  for (std::size_t i = 0; i < 2 * w + 1; ++i) sum += gap_v[i];
  for (std::size_t i = w; i + w < n; ++i) {
    if (i > w) sum += gap_v[i + w] - gap_v[i - w - 1];
    if (moves_before[i + w] != moves_before[i - w]) continue;
    const double about_mean = gap_v[i] - sum / static_cast<double>(2 * w + 1);
    level_sq.push_back(about_mean * about_mean);
    level_s2.push_back(sensitivity_v_per_mm[i] * sensitivity_v_per_mm[i]);
  }
  // The moving mean takes 1 / (2w + 1) of white variance with it.
  const double kept = 1.0 - 1.0 / static_cast<double>(2 * w + 1);
  const VibrationSignature by_levels = regress_on_sensitivity(level_sq, level_s2, 1.0 / kept);
  // Each sees part of the motion's spectrum: the larger estimate of it is kept; the white noise
  // beside it is the differences' (the levels' holds what the moving mean let through).
  VibrationSignature signature = by_differences;
  signature.present = by_differences.present || by_levels.present;
  signature.slope_t = std::max(by_differences.slope_t, by_levels.slope_t);
  signature.rms_mm = std::max(by_differences.rms_mm, by_levels.rms_mm);
  return signature;
}

}  // namespace flange::diagnose
