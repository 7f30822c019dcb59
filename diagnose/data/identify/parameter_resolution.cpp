// SPDX-License-Identifier: MIT
#include "parameter_resolution.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "compensated_sensitivity.h"
#include "criteria.h"
#include "effect_classes.h"
#include "hypothetical_session.h"
#include "parallel_work.h"
#include "recorded_level.h"
#include "series_arithmetic.h"
#include "series_statistics.h"

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

std::string number(double v) { return fmt::format("{:.6g}", v); }

Eigen::VectorXd sensitivities(const Eigen::MatrixXd& columns) {
  return compensated_sensitivity(columns.transpose() * columns, columns.rows());
}

// The largest RMS change of the twin's voltage on `operating_range` at either end of `profile`.
double change_outside(const TwinReplay& operating_range, const std::vector<double>& fitted_v,
                      const ValueProfile& profile) {
  double most = 0.0;
  for (const ProfileEnd* end : {&profile.low, &profile.high}) {
    most = std::max(most, rms_of(minus(operating_range.voltage(end->modelled), fitted_v)));
  }
  return most;
}

ValueJudgement judge(const ValueProfile& profile, double change_outside_v, double noise_v) {
  ValueJudgement out;
  if ((profile.low.at_edge && profile.high.at_edge) ||
      change_outside_v > criteria::kMostChangeOutsideTheRecording * noise_v) {
    out.undetermined = true;
  } else if (profile.low.at_edge) {
    out.bound = "<= " + number(profile.high.value);
  } else if (profile.high.at_edge) {
    out.bound = ">= " + number(profile.low.value);
  }
  return out;
}

void resolve_library_picks(const Parts& parts, Selection& selection, double noise_v) {
  const PickValues found = library_values(selection);
  if (found.values.empty()) return;
  const Eigen::MatrixXd columns = value_columns(parts.cal_replay, selection.modelled, found.values);
  const Eigen::VectorXd sensitivity = sensitivities(columns);
  const RecordingSeries range_session = operating_range_session(parts.calibration);
  const TwinReplay operating_range(range_session, parts.cal_replay.nominal());
  std::vector<std::size_t> every(found.values.size());
  std::iota(every.begin(), every.end(), std::size_t{0});
  const std::vector<ValueJudgement> judged = judge_values(
      parts.cal_replay, operating_range, selection.modelled, found.values, every, noise_v);
  for (std::size_t k = 0; k < found.values.size(); ++k) {
    EffectFinding& finding = selection.picks[found.pick[k]].finding;
    const std::string& key = found.values[k].range.key;
    finding.resolution[key] = resolution_of(sensitivity(static_cast<Eigen::Index>(k)), noise_v);
    if (judged[k].undetermined) finding.undetermined.push_back(key);
    if (!judged[k].bound.empty()) finding.bounds[key] = judged[k].bound;
  }
  const Eigen::MatrixXd gram = columns.transpose() * columns;
  for (std::size_t j = 0; j < selection.picks.size(); ++j) {
    std::vector<std::size_t> own;
    for (std::size_t k = 0; k < found.values.size(); ++k) {
      if (found.pick[k] == j) own.push_back(k);
    }
    if (own.empty()) continue;
    selection.picks[j].finding.level = recorded_level(parts.calibration, selection.modelled,
                                                      found.values, own, gram, columns.rows(),
                                                      noise_v);
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

double resolution_of(double sensitivity, double noise_v) {
  if (sensitivity <= 0.0) return std::numeric_limits<double>::infinity();
  return std::sqrt(criteria::kScoreResolution) * noise_v / sensitivity;
}

double resolution_noise(const Selection& selection) {
  return std::max(selection.noise_v, criteria::kTieFloorShareOfGap * rms_of(selection.raw_ho_gap));
}

std::vector<ValueJudgement> judge_values(const TwinReplay& replay,
                                         const TwinReplay& operating_range,
                                         const std::vector<sim::EffectSettings>& modelled,
                                         const std::vector<ModelledValue>& values,
                                         const std::vector<std::size_t>& which, double noise_v) {
  const TwinReplay& search = replay.search_replay();
  const Eigen::MatrixXd columns = value_columns(search, modelled, values);
  const Eigen::VectorXd sensitivity = sensitivities(columns);
  const std::vector<double> fitted_outside = operating_range.voltage(modelled);
  return parallel_map<ValueJudgement>(which.size(), [&](std::size_t i) {
    const std::size_t k = which[i];
    const double r = resolution_of(sensitivity(static_cast<Eigen::Index>(k)), noise_v);
    const ValueProfile profile = profile_value(search, modelled, values, columns, k, r, noise_v);
    return judge(profile, change_outside(operating_range, fitted_outside, profile), noise_v);
  });
}

Selection resolve_parameters(const Parts& parts, Selection selection) {
  const double noise_v = resolution_noise(selection);
  for (Pick& pick : selection.picks) {
    pick.finding.resolution.clear();
    pick.finding.undetermined.clear();
    pick.finding.bounds.clear();
    pick.finding.level.reset();
    if (pick.modelled_index < 0 && pick.chosen().free_shape) {
      resolve_free_shape(*pick.chosen().free_shape, noise_v, pick.finding);
    }
  }
  resolve_library_picks(parts, selection, noise_v);
  return selection;
}

}  // namespace flange::diagnose
