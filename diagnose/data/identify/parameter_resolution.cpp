// SPDX-License-Identifier: MIT
#include "parameter_resolution.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "compensated_sensitivity.h"
#include "criteria.h"
#include "effect_classes.h"
#include "series_statistics.h"
#include "series_arithmetic.h"

namespace flange::diagnose {
namespace {

// The searched parameters of every library pick, with the pick each belongs to.
struct PickValues {
  std::vector<ModelledValue> values;
  std::vector<std::size_t> pick;
};

PickValues library_values(const Selection& selection) {
  PickValues out;
  for (std::size_t j = 0; j < selection.picks.size(); ++j) {
    const Pick& pick = selection.picks[j];
    if (pick.modelled_index < 0) continue;
    const auto index = static_cast<std::size_t>(pick.modelled_index);
    const sim::EffectSettings& effect = selection.modelled[index];
    for (const SearchRange& range : effect_class(effect.name).search) {
      if (effect.params.count(range.key) == 0) continue;
      out.values.push_back({index, range});
      out.pick.push_back(j);
    }
  }
  return out;
}

Eigen::VectorXd derivative(const TwinReplay& replay,
                           const std::vector<sim::EffectSettings>& modelled,
                           const ModelledValue& value) {
  const double at = modelled[value.effect].params.at(value.range.key);
  const double h = 1e-4 * (value.range.hi - value.range.lo);
  const double up = std::min(at + h, value.range.hi), down = std::max(at - h, value.range.lo);
  std::vector<sim::EffectSettings> moved = modelled;
  moved[value.effect].params[value.range.key] = up;
  const std::vector<double> v_up = replay.voltage(moved);
  moved[value.effect].params[value.range.key] = down;
  const std::vector<double> v_down = replay.voltage(moved);
  Eigen::VectorXd column(static_cast<Eigen::Index>(v_up.size()));
  for (std::size_t i = 0; i < v_up.size(); ++i) {
    column(static_cast<Eigen::Index>(i)) = (v_up[i] - v_down[i]) / (up - down);
  }
  return column;
}

std::string number(double v) { return fmt::format("{:.6g}", v); }

// What the data say of one library value, at `at` with resolution `r`.
void judge_library_value(const SearchRange& range, double at, double r, EffectFinding& finding) {
  finding.resolution[range.key] = r;
  if (undetermined_within(range, at, r)) {
    finding.undetermined.push_back(range.key);
  } else if (at - r <= range.lo) {
    finding.bounds[range.key] = "<= " + number(at + r);
  } else if (at + r >= range.hi) {
    finding.bounds[range.key] = ">= " + number(at - r);
  }
}

void resolve_library_picks(const Parts& parts, Selection& selection, double noise_v) {
  const PickValues found = library_values(selection);
  if (found.values.empty()) return;
  const Eigen::VectorXd sensitivity =
      value_sensitivity(parts.cal_replay, selection.modelled, found.values);
  for (std::size_t k = 0; k < found.values.size(); ++k) {
    EffectFinding& finding = selection.picks[found.pick[k]].finding;
    const SearchRange& range = found.values[k].range;
    judge_library_value(range, finding.params.at(range.key),
                        resolution_of(sensitivity(static_cast<Eigen::Index>(k)), noise_v), finding);
  }
}

void resolve_free_shape(const FreeShapeFit& shape, double noise_v, EffectFinding& finding) {
  double largest = 0.0;
  for (const auto& [name, sensitivity] : shape.value_sensitivity_v) {
    largest = std::max(largest, std::abs(shape.params.at(name)));
  }
  for (const auto& [name, sensitivity] : shape.value_sensitivity_v) {
    const double r = resolution_of(sensitivity, noise_v);
    finding.resolution[name] = r;
    if (r > largest) finding.undetermined.push_back(name);
  }
  // A searched value pressed against an edge of its search is a bound, not a finding.
  for (const auto& [name, bound] : shape.search_edges) finding.bounds[name] = bound;
}

}  // namespace

Eigen::VectorXd value_sensitivity(const TwinReplay& replay,
                                  const std::vector<sim::EffectSettings>& modelled,
                                  const std::vector<ModelledValue>& values) {
  Eigen::MatrixXd columns(static_cast<Eigen::Index>(replay.size()),
                          static_cast<Eigen::Index>(values.size()));
  for (std::size_t k = 0; k < values.size(); ++k) {
    columns.col(static_cast<Eigen::Index>(k)) = derivative(replay, modelled, values[k]);
  }
  return compensated_sensitivity(columns.transpose() * columns, columns.rows());
}

bool undetermined_within(const SearchRange& range, double at, double resolution) {
  const double open = std::min(range.hi, at + resolution) - std::max(range.lo, at - resolution);
  return open >= criteria::kUndeterminedShareOfSearch * (range.hi - range.lo);
}

double resolution_of(double sensitivity, double noise_v) {
  if (sensitivity <= 0.0) return std::numeric_limits<double>::infinity();
  return std::sqrt(criteria::kScoreResolution) * noise_v / sensitivity;
}

double resolution_noise(const Selection& selection) {
  return std::max(selection.noise_v, criteria::kTieFloorShareOfGap * rms_of(selection.raw_ho_gap));
}

void resolve_parameters(const Parts& parts, Selection& selection) {
  const double noise_v = resolution_noise(selection);
  for (Pick& pick : selection.picks) {
    pick.finding.resolution.clear();
    pick.finding.undetermined.clear();
    pick.finding.bounds.clear();
    if (pick.modelled_index < 0 && pick.chosen().free_shape) {
      resolve_free_shape(*pick.chosen().free_shape, noise_v, pick.finding);
    }
  }
  resolve_library_picks(parts, selection, noise_v);
}

}  // namespace flange::diagnose
