// SPDX-License-Identifier: MIT
#include "mains_family.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "family_makers.h"
#include "line_source.h"
#include "mains_lines.h"
#include "series_arithmetic.h"

namespace flange::diagnose::free_shapes {

void MainsFamily::search(const RecordedPart& calibration, const std::vector<double>& gap_v) {
  const std::vector<double>& t = calibration.series.t_s;
  if (t.size() < 2) return;
  const double fs_hz = rate_of_median_step(t);
  const MainsAliases aliases = mains_aliases(fs_hz);
  // The aliases with a line on the calibration part, unless the lines are motion.
  cal_lines_ = find_lines(t, gap_v, aliases.distinct_hz);
  if (!cal_lines_.empty() &&
      line_source({{calibration, gap_v}}, cal_lines_).source == LineSource::kMotion) {
    cal_lines_.clear();
    follow_sensitivity_ = true;
  }
  // The mains the lines belong to. An alias can be a line of both (3 Hz at 9 Hz: 60 Hz, or the
  // 3rd harmonic of 50 Hz); pickup is mostly the fundamental, so each line counts 1/h for the
  // lowest harmonic h of each mains near it, and the mains with the larger sum is kept.
  double score_50 = 0.0, score_60 = 0.0;
  for (double f : cal_lines_) {
    const auto lowest_harmonic = [&](double mains_hz) {
      for (int h = 1; h <= kMainsHarmonics; ++h) {
        if (std::abs(f - alias_hz(h * mains_hz, fs_hz)) <= kMainsSearchHz + 1e-9) return 1.0 / h;
      }
      return 0.0;
    };
    score_50 += lowest_harmonic(50.0);
    score_60 += lowest_harmonic(60.0);
  }
  if (!cal_lines_.empty()) mains_hz_ = score_60 > score_50 ? 60.0 : 50.0;
  for (double f : cal_lines_) {
    for (double alias : aliases.distinct_hz) {
      if (std::abs(f - alias) <= kMainsSearchHz + 1e-9 &&
          std::find(tones_hz_.begin(), tones_hz_.end(), alias) == tones_hz_.end()) {
        tones_hz_.push_back(alias);
      }
    }
  }
  // A harmonic of the lines' mains that the sampling folds onto 0 Hz (the 3rd of 50 Hz at 6 Hz)
  // is a constant in each session, set by the mains' phase when the session starts: an offset
  // that differs from session to session by up to twice that harmonic's amplitude. Nothing
  // carries it from one session to the other, so each part's own constant joins the lines. Only
  // the mains the lines belong to counts: the other one's harmonic on 0 Hz would add a constant
  // of each session's own that no pickup makes.
  for (const MainsAlias& alias : aliases.of_harmonics) {
    if (alias.mains_hz != mains_hz_) continue;
    const bool has_line = std::any_of(tones_hz_.begin(), tones_hz_.end(), [&](double f) {
      return std::abs(f - alias.hz) <= kMainsSearchHz + 1e-9;
    });
    for (int h = 1; has_line && dc_harmonic_hz_ == 0.0 && h <= kMainsHarmonics; ++h) {
      if (alias_hz(h * alias.mains_hz, fs_hz) <= kDcAliasHz) dc_harmonic_hz_ = h * alias.mains_hz;
    }
  }
}

FreeShapeFit MainsFamily::fit(const FreeShapeInputs& in) {
  FreeShapeFit fit;
  if (empty()) {
    fit.cal_voltage_v.assign(in.cal_gap_v.size(), 0.0);
    fit.heldout_voltage_v.assign(in.ho_gap_v.size(), 0.0);
    fit.description = lines_are_motion()
                          ? "lines at aliases of the mains whose power follows the sensor's "
                            "sensitivity from window to window: mount motion, not pickup"
                          : "no line at an alias of the mains";
    return fit;
  }
  fit.cal_voltage_v = fitted_on_calibration(in.calibration, in.cal_gap_v);
  fit.heldout_voltage_v = fitted(in.heldout, in.ho_gap_v, fit.heldout_values);
  describe(fit, fit.cal_voltage_v);
  fit.free_values = 3 * static_cast<int>(lines());  // frequency, amplitude and phase
  return fit;
}

std::vector<double> MainsFamily::with_session_constant(std::vector<double> tones,
                                                       const std::vector<double>& gap_v) const {
  if (dc_harmonic_hz_ == 0.0 || tones.empty()) return tones;
  double left = 0.0;
  for (std::size_t i = 0; i < tones.size(); ++i) left += gap_v[i] - tones[i];
  const double constant = left / static_cast<double>(tones.size());
  for (double& v : tones) v += constant;
  return tones;
}

std::vector<double> MainsFamily::fitted_on_calibration(const RecordedPart& calibration,
                                                       const std::vector<double>& gap_v) const {
  int values = 0;
  return with_session_constant(windowed_tones(calibration.series.t_s, gap_v, cal_lines_, values),
                               gap_v);
}

// Windows of 20 s, or 10 or 5 s where those fit better: a grid whose frequency wanders by
// 0.01 Hz turns a line by a fifth of a cycle across 20 s against the window's own frequency (a
// harmonic by as many times more), which a shorter window halves. Each window's values take
// about their share of white noise, values/n of its variance, off the mean square; what a window
// length leaves, times 1 + 2 values/n, is what it would leave on new noise, and the least is kept.
std::vector<double> MainsFamily::fitted(const RecordedPart& part, const std::vector<double>& gap_v,
                                        int& values) const {
  // Each part's own lines near the aliases kept: the grid wanders between sessions.
  const std::vector<double> lines = find_lines(part.series.t_s, gap_v, tones_hz_);
  std::vector<double> tones;
  double best = std::numeric_limits<double>::infinity();
  const auto n = static_cast<double>(gap_v.size());
  for (const double window_s : {kMainsWindowS, kMainsWindowS / 2, kMainsWindowS / 4}) {
    int window_values = 0;
    std::vector<double> fitted =
        windowed_tones(part.series.t_s, gap_v, lines, window_values, window_s);
    double left = 0.0;
    for (std::size_t i = 0; i < gap_v.size(); ++i) left += std::pow(gap_v[i] - fitted[i], 2);
    const double expected = left / n * (1.0 + 2.0 * window_values / n);
    if (expected < best) {
      best = expected;
      tones = std::move(fitted);
      values = window_values;
    }
  }
  values += static_cast<int>(lines.size());  // their frequencies
  if (dc_harmonic_hz_ > 0.0) ++values;       // the session's constant
  return with_session_constant(std::move(tones), gap_v);
}

void MainsFamily::describe(FreeShapeFit& fit, const std::vector<double>& cal_tones_v) const {
  std::string lines;
  for (std::size_t k = 0; k < cal_lines_.size(); ++k) {
    fit.params[fmt::format("line_hz_{}", k + 1)] = cal_lines_[k];
    lines += fmt::format("{}{:.4g} Hz", k == 0 ? "" : ", ", cal_lines_[k]);
  }
  const double rms = std::sqrt(mean_square(cal_tones_v));
  fit.params["rms_v"] = rms;
  fit.params["mains_hz"] = mains_hz_;
  fit.description = fmt::format(
      "lines at the aliases of the mains ({} on the calibration part), {:.3g} V RMS, their "
      "amplitude and phase free in every {:g} s window of each session (the mains' phase at a "
      "session's start is arbitrary; on the held-out session {:g} or {:g} s windows where they "
      "fit better, for a grid whose frequency wanders)",
      lines, rms, kMainsWindowS, kMainsWindowS / 2, kMainsWindowS / 4);
  if (dc_harmonic_hz_ > 0.0) {
    fit.params["dc_harmonic_hz"] = dc_harmonic_hz_;
    fit.description += fmt::format(
        "; and a constant of each session's own: the mains' {:g} Hz harmonic lands on 0 Hz at "
        "this rate, an offset set by the mains' phase when the session starts",
        dc_harmonic_hz_);
  }
}

std::unique_ptr<Family> make_mains_lines(const RecordedPart&) {
  return std::make_unique<MainsFamily>();
}

}  // namespace flange::diagnose::free_shapes
