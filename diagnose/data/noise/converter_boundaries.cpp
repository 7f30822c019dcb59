// SPDX-License-Identifier: MIT
#include "converter_boundaries.h"

#include <algorithm>
#include <limits>
#include <numeric>

#include "criteria.h"
#include "effect_classes.h"
#include "series_statistics.h"
#include "series_arithmetic.h"

namespace flange::diagnose {
namespace {

double mean_of_all(const std::vector<double>& x) {
  return std::accumulate(x.begin(), x.end(), 0.0) / static_cast<double>(x.size());
}

// The threshold, among 21 places over [-0.5, 0.5] LSB, at which the twin's converter on `grid`
// fits the calibration part best, and the twin's voltage with it there.
std::pair<double, std::vector<double>> best_threshold(const Parts& parts, const AdcGrid& grid,
                                                      const std::vector<sim::EffectSettings>& modelled) {
  const std::vector<double>& cal_v = parts.calibration.voltage_v;
  double best_rms = std::numeric_limits<double>::infinity(), best = 0.0;
  std::vector<double> best_v;
  for (int step = -10; step <= 10; ++step) {
    sim::EffectSettings converter = grid.as_effect();
    converter.params["threshold_lsb"] = 0.05 * step;
    std::vector<sim::EffectSettings> with = modelled;
    with.push_back(converter);
    std::vector<double> v = parts.cal_replay.voltage(with);
    const double rms = rms_of(minus(cal_v, v));
    if (rms < best_rms) {
      best_rms = rms;
      best = converter.params["threshold_lsb"];
      best_v = std::move(v);
    }
  }
  return {best, std::move(best_v)};
}

// A DAQ gain calibration on `gap` (the calibration gap the placed boundaries leave): the constant
// beside the grid's gain, kept when it lowers the gap's mean square by `least` (gap then holds
// what it leaves).
std::optional<double> gain_calibration_offset(std::vector<double>& gap, double slope,
                                              const std::vector<double>& twin_v, double least) {
  if (slope == 0.0) return std::nullopt;
  std::vector<double> line_gap = gap;
  for (std::size_t i = 0; i < line_gap.size(); ++i) line_gap[i] -= slope * twin_v[i];
  const double line_offset_v = mean_of_all(line_gap);
  for (double& g : line_gap) g -= line_offset_v;
  const double before = rms_of(gap), after = rms_of(line_gap);
  if (!(before * before - after * after >= least)) return std::nullopt;
  gap = std::move(line_gap);
  return line_offset_v;
}

}  // namespace

std::optional<ConverterPlacement> place_converter_boundaries(
    const Parts& parts, const std::vector<sim::EffectSettings>& modelled, double noise_v) {
  const bool modelled_already = std::any_of(modelled.begin(), modelled.end(), [](const auto& e) {
    return effect_class(e.name).is_converter;
  });
  if (modelled_already || !parts.grid) return std::nullopt;
  const AdcGrid& grid = *parts.grid;
  const std::vector<double>& cal_v = parts.calibration.voltage_v;
  const std::vector<double> twin_v = parts.cal_replay.voltage(modelled);
  const auto [threshold, best_v] = best_threshold(parts, grid, modelled);
  const double offset_v = mean_of_all(minus(best_v, twin_v));
  const std::vector<double> raw_gap = minus(cal_v, twin_v);
  std::vector<double> gap = raw_gap;
  for (double& g : gap) g -= offset_v;
  const double least = criteria::kConverterPlacementGain * noise_v * noise_v;
  const double slope = grid.calibration_gain - 1.0;
  const std::optional<double> line_offset_v = gain_calibration_offset(gap, slope, twin_v, least);
  const double without = rms_of(raw_gap), after = rms_of(gap);
  if (without * without - after * after < least) return std::nullopt;
  ConverterPlacement placement;
  placement.threshold_lsb = threshold;
  placement.offset_v = offset_v;
  placement.cal_added_v.assign(parts.calibration.size(), offset_v);
  placement.ho_added_v.assign(parts.heldout.size(), offset_v);
  if (line_offset_v) {
    const std::vector<double> ho_twin_v = parts.ho_replay.voltage(modelled);
    for (std::size_t i = 0; i < twin_v.size(); ++i) {
      placement.cal_added_v[i] += slope * twin_v[i] + *line_offset_v;
    }
    for (std::size_t i = 0; i < ho_twin_v.size(); ++i) {
      placement.ho_added_v[i] += slope * ho_twin_v[i] + *line_offset_v;
    }
    placement.gain = grid.calibration_gain;
    placement.gain_offset_v = *line_offset_v;
  }
  return placement;
}

}  // namespace flange::diagnose
