// SPDX-License-Identifier: MIT
#include "aliased_lines.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "effect_classes.h"
#include "line_source.h"
#include "mains_lines.h"
#include "sample_rate.h"
#include "separating_rate.h"
#include "series_arithmetic.h"

namespace flange::diagnose {
namespace {

double param_or(const EffectFinding& finding, const std::string& key, double fallback) {
  const auto it = finding.params.find(key);
  return it == finding.params.end() ? fallback : it->second;
}

// The harmonics (up to free_shapes::kMainsHarmonics) of `mains_hz` that fold to within the line
// search's reach of `line_hz` at `fs_hz`.
std::vector<double> harmonics_on_line(double mains_hz, double line_hz, double fs_hz) {
  std::vector<double> out;
  for (int h = 1; h <= free_shapes::kMainsHarmonics; ++h) {
    if (std::abs(folded_hz(h * mains_hz, fs_hz) - line_hz) <= free_shapes::kMainsSearchHz) {
      out.push_back(h * mains_hz);
    }
  }
  return out;
}

// The lines in groups, each of lines within twice the line search's reach of the group's first:
// the lines near one alias, judged together (two lines 0.04 Hz apart share a 20 s window's fit).
std::vector<std::vector<double>> line_groups(const std::vector<double>& lines_hz) {
  std::vector<std::vector<double>> groups;
  for (const double f : lines_hz) {
    const auto near = std::find_if(groups.begin(), groups.end(), [&](const auto& g) {
      return std::abs(g.front() - f) <= 2.0 * free_shapes::kMainsSearchHz;
    });
    if (near == groups.end()) {
      groups.push_back({f});
    } else {
      near->push_back(f);
    }
  }
  return groups;
}

// "4, 8, 10, 14, ... Hz": the first few of `hz`.
std::string some_of(const std::vector<double>& hz) {
  constexpr std::size_t kShown = 6;
  std::string out;
  for (std::size_t k = 0; k < std::min(hz.size(), kShown); ++k) {
    out += fmt::format("{}{:.4g}", k == 0 ? "" : ", ", hz[k]);
  }
  return out + (hz.size() > kShown ? ", ..." : "");
}

}  // namespace

std::vector<double> mains_pick_lines_hz(const EffectFinding& finding, double fs_hz) {
  std::vector<double> lines;
  for (const auto& [key, value] : finding.params) {
    if (key.rfind("line_hz_", 0) == 0) lines.push_back(value);
  }
  if (!lines.empty()) return lines;
  const double mains_hz = param_or(finding, "mains_hz", 0.0);
  const int harmonics = param_or(finding, "harmonic_ratio", 0.0) > 0.0
                            ? static_cast<int>(param_or(finding, "harmonics", 1.0))
                            : 1;
  for (int h = 1; h <= harmonics; ++h) {
    const double f = folded_hz(h * mains_hz, fs_hz);
    const bool shows = f >= free_shapes::kMainsSearchHz + 2.0 / free_shapes::kMainsWindowS &&
                       f <= 0.5 * fs_hz - free_shapes::kMainsSearchHz;
    if (shows && std::find(lines.begin(), lines.end(), f) == lines.end()) lines.push_back(f);
  }
  return lines;
}

void judge_aliased_lines(const Parts& parts, Selection& selection) {
  const auto motion = std::find_if(effect_classes().begin(), effect_classes().end(),
                                   [](const EffectClass& c) { return c.is_mount_motion; });
  if (motion == effect_classes().end()) return;
  const double fs_hz = sample_rate_hz(parts.calibration);
  const std::vector<sim::EffectSettings> given(
      selection.modelled.begin(),
      selection.modelled.begin() + static_cast<std::ptrdiff_t>(selection.first_selected));
  const std::vector<double> cal_gap =
      minus(parts.calibration.voltage_v, parts.cal_replay.voltage(given));
  const RecordedPart cal = parts.cal();
  const RecordedPart ho = parts.ho();
  for (Pick& pick : selection.picks) {
    if (!effect_class(pick.finding.name).lines_of_each_session) continue;
    const std::vector<double> lines = mains_pick_lines_hz(pick.finding, fs_hz);
    if (lines.empty()) continue;
    bool pickup = true;
    for (const std::vector<double>& group : line_groups(lines)) {
      pickup = pickup && free_shapes::line_source({{cal, cal_gap}, {ho, selection.raw_ho_gap}},
                                                  group)
                                 .source == free_shapes::LineSource::kPickup;
    }
    std::vector<std::string>& alike = pick.finding.indistinguishable_from;
    if (!pickup && std::find(alike.begin(), alike.end(), motion->name) == alike.end()) {
      alike.push_back(motion->name);
    }
  }
}

std::string tell_line_from_motion(const Parts& parts, const EffectFinding& pick,
                                  const std::string& motion) {
  const double fs_hz = sample_rate_hz(parts.calibration);
  const double mains_hz = param_or(pick, "mains_hz", 0.0);
  const std::string clearances = fmt::format(
      "a session whose clearance steps over the range (or whose temperature changes) so that the "
      "sensitivity dV/dd changes: a line of {} then follows it, one of {} does not",
      motion, pick.name);
  // The first line where a harmonic of the pick's mains folds at this rate.
  for (const double line_hz : mains_pick_lines_hz(pick, fs_hz)) {
    const std::vector<double> harmonics = harmonics_on_line(mains_hz, line_hz, fs_hz);
    const std::optional<double> rate = separating_rate_hz(line_hz, fs_hz, harmonics);
    if (!rate) continue;
    return fmt::format(
        "to tell {} from {}: the line at {:.3g} Hz is where {:g} Hz folds at {:.4g} Hz sampling, "
        "and where motion at {} Hz folds; a session sampled at {:g} Hz, where {:g} Hz folds to "
        "{:.3g} Hz and motion at any of those frequencies (up to {:g} Hz) folds at least {:g} Hz "
        "away, or {}",
        pick.name, motion, line_hz, harmonics.front(), fs_hz,
        some_of(motion_folding_onto(line_hz, fs_hz, harmonics)), *rate, harmonics.front(),
        folded_hz(harmonics.front(), *rate), kHighestMotionHz, kSeparatedLinesHz, clearances);
  }
  return fmt::format("to tell {} from {}: {}", pick.name, motion, clearances);
}

}  // namespace flange::diagnose
