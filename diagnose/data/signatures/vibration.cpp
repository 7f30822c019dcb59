// SPDX-License-Identifier: MIT
#include "vibration.h"

#include <algorithm>
#include <cmath>

#include "criteria.h"
#include "effect_classes.h"
#include "evidence.h"
#include "series_statistics.h"
#include "series_arithmetic.h"
#include "verdict_reasons.h"
#include "vibration_signature.h"

namespace flange::diagnose {

double vibration_inclusion(const std::vector<double>& gap, const TwinReplay& replay,
                           const RecordingSeries& series, const BlockResamples& resamples) {
  int shows = 0;
  for (std::size_t r = 0; r < resamples.size(); ++r) {
    std::vector<double> gap_drawn, sens_drawn, clearance_drawn;
    for (std::size_t i : resamples.indices(r)) {
      gap_drawn.push_back(gap[i]);
      sens_drawn.push_back(replay.sensitivity_v_per_mm()[i]);
      clearance_drawn.push_back(series.clearance_mm[i]);
    }
    if (vibration_signature(gap_drawn, sens_drawn, clearance_drawn).present) ++shows;
  }
  return static_cast<double>(shows) / static_cast<double>(resamples.size());
}

double motion_mean_square_over_part(const std::vector<double>& left,
                                    const std::vector<double>& sensitivity_v_per_mm, double sigma,
                                    double white_allowed) {
  const double mean = mean_of(left);
  std::vector<double> departure_sq(left.size()), s2(left.size());
  for (std::size_t i = 0; i < left.size(); ++i) {
    departure_sq[i] = std::pow(left[i] - mean, 2);
    s2[i] = std::pow(sensitivity_v_per_mm[i], 2);
  }
  const LineFit fit = line_fit(s2, departure_sq);
  const bool noise_beside =
      fit.intercept >= 0.5 * sigma * sigma && fit.intercept <= white_allowed * white_allowed;
  return fit.fitted && fit.slope > 0.0 && noise_beside ? fit.slope : 0.0;
}

VerdictNoise recognise_vibration(const Parts& parts, Selection& selection) {
  const std::vector<double>& current_error = selection.current_error;
  const std::vector<double> cal_after =
      minus(cal_target(parts, selection), parts.cal_replay.voltage(selection.modelled));
  const VibrationSignature cal_vibration = vibration_signature(
      cal_after, parts.cal_replay.sensitivity_v_per_mm(), parts.calibration.clearance_mm);
  const VibrationSignature ho_vibration = vibration_signature(
      current_error, parts.ho_replay.sensitivity_v_per_mm(), parts.heldout.clearance_mm);
  const double sigma = selection.noise_v;
  if (!cal_vibration.present || !ho_vibration.present) return {sigma, ""};
  // The mean squared difference over the pairs the signature took (at rest, where it rests).
  const std::vector<bool> rest = pairs_at_rest(parts.heldout.clearance_mm);
  double sum = 0.0;
  std::size_t pairs = 0;
  for (std::size_t i = 0; i + 1 < current_error.size(); ++i) {
    if (!rest.empty() && !rest[i]) continue;
    sum += std::pow(current_error[i + 1] - current_error[i], 2);
    ++pairs;
  }
  // The motion's own variance on the held-out part, (rms_mm dV/dd)^2 on average, beside the white
  // noise: motion whose aliases fall low escapes the differences. rms_mm^2 is the signature's or,
  // where larger, the mean square over the whole parts; the same mount shakes both, so the smaller
  // of those two counts, and what a pick's shape misses on one part alone does not pass for motion.
  const double session_mean_square_mm2 =
      std::min(motion_mean_square_over_part(cal_after, parts.cal_replay.sensitivity_v_per_mm(),
                                            sigma, criteria::kExplainedRatio * sigma),
               motion_mean_square_over_part(current_error, parts.ho_replay.sensitivity_v_per_mm(),
                                            sigma, criteria::kExplainedRatio * sigma));
  const double motion_mean_square_mm2 =
      std::max(ho_vibration.rms_mm * ho_vibration.rms_mm, session_mean_square_mm2);
  double mean_sensitivity_sq = 0.0;
  for (const double s : parts.ho_replay.sensitivity_v_per_mm()) mean_sensitivity_sq += s * s;
  mean_sensitivity_sq /= static_cast<double>(std::max<std::size_t>(current_error.size(), 1));
  const double motion_variance = motion_mean_square_mm2 * mean_sensitivity_sq;
  const double verdict_noise =
      std::max({sigma, std::sqrt(0.5 * sum / static_cast<double>(std::max<std::size_t>(pairs, 1))),
                std::sqrt(sigma * sigma + motion_variance)});
  EffectFinding finding;
  finding.name = motion_class();
  finding.params = {{"rms_mm", cal_vibration.rms_mm}};
  finding.noise_type = true;
  finding.heldout_rms_before = finding.heldout_rms_after = rms_of(current_error);
  finding.inclusion =
      vibration_inclusion(current_error, parts.ho_replay, parts.heldout, selection.resamples);
  finding.evidence =
      evidence::mount_motion(cal_vibration.slope_t, ho_vibration.slope_t, ho_vibration.rms_mm);
  selection.vibration = finding;
  if (verdict_noise <= sigma) return {sigma, ""};
  return {verdict_noise, reasons::motion_in_the_noise(verdict_noise, sigma)};
}

}  // namespace flange::diagnose
