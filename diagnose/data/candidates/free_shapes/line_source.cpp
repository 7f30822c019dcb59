// SPDX-License-Identifier: MIT
#include "line_source.h"

#include <cmath>

#include "criteria.h"
#include "mains_lines.h"

namespace flange::diagnose::free_shapes {
namespace {

// The fewest windows the slope is fitted on.
constexpr std::size_t kLeastWindowsForTheSlope = 8;

struct WindowPowers {
  std::vector<double> sensitivity2, power;
};

void add_windows(const PartGap& in, const std::vector<double>& lines_hz, WindowPowers& out) {
  const std::vector<double>& t = in.part.series.t_s;
  const std::vector<double>& s = in.part.replay.sensitivity_v_per_mm();
  int values = 0;
  const std::vector<double> tones = windowed_tones(t, in.gap_v, lines_hz, values);
  for (const auto& [begin, end] : mains_windows(t)) {
    double p = 0.0, q = 0.0;
    for (std::size_t i = begin; i < end; ++i) {
      p += tones[i] * tones[i];
      q += s[i] * s[i];
    }
    out.power.push_back(p / static_cast<double>(end - begin));
    out.sensitivity2.push_back(q / static_cast<double>(end - begin));
  }
}

}  // namespace

// Least squares p = a + b x over the windows (x the mean (dV/dd)^2). Pickup gives b = 0; motion
// b = mean p / mean x (its power is proportional to x; the white noise the lines take in each
// window adds a little to a). The slope's standard error comes from the scatter about the fit,
// which holds a narrow band's window-to-window fluctuation as well as the noise's.
LineSourceJudgement line_source(const std::vector<PartGap>& parts,
                                const std::vector<double>& lines_hz) {
  LineSourceJudgement judged;
  if (lines_hz.empty()) return judged;
  WindowPowers w;
  for (const PartGap& part : parts) add_windows(part, lines_hz, w);
  const std::size_t n = w.power.size();
  judged.windows = n;
  if (n < kLeastWindowsForTheSlope) return judged;
  double mx = 0.0, mp = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    mx += w.sensitivity2[k] / static_cast<double>(n);
    mp += w.power[k] / static_cast<double>(n);
  }
  double sxx = 0.0, sxp = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    sxx += (w.sensitivity2[k] - mx) * (w.sensitivity2[k] - mx);
    sxp += (w.sensitivity2[k] - mx) * (w.power[k] - mp);
  }
  // A spread of (dV/dd)^2 below a millionth of its mean is rounding: dV/dd is constant.
  if (mx <= 0.0 || mp <= 0.0 || sxx <= 1e-12 * mx * mx * static_cast<double>(n)) return judged;
  const double slope = sxp / sxx;
  double residual = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    residual += std::pow(w.power[k] - mp - slope * (w.sensitivity2[k] - mx), 2);
  }
  const double se = std::sqrt(residual / static_cast<double>(n - 2) / sxx);
  if (!(se > 0.0)) return judged;
  judged.slope_t = slope / se;
  judged.separation = mp / mx / se;
  if (judged.slope_t > criteria::kMotionLineT) {
    judged.source = LineSource::kMotion;
  } else if (judged.separation >= criteria::kLineSourceSeparation) {
    judged.source = LineSource::kPickup;
  }
  return judged;
}

}  // namespace flange::diagnose::free_shapes
