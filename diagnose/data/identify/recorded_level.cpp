// SPDX-License-Identifier: MIT
#include "recorded_level.h"

#include <cmath>
#include <limits>
#include <numeric>

#include "compensated_sensitivity.h"
#include "criteria.h"
#include "effect_classes.h"

namespace flange::diagnose {

std::optional<EffectLevel> recorded_level(const RecordingSeries& calibration,
                                          const std::vector<sim::EffectSettings>& modelled,
                                          const std::vector<ModelledValue>& values,
                                          const std::vector<std::size_t>& own,
                                          const Eigen::MatrixXd& gram, Eigen::Index rows,
                                          double noise_v) {
  if (own.empty() || calibration.temp_c.empty()) return std::nullopt;
  const sim::EffectSettings& effect = modelled[values[own.front()].effect];
  const std::optional<TemperatureLevel>& law = effect_class(effect.name).level;
  if (!law) return std::nullopt;
  const double temp_c =
      std::accumulate(calibration.temp_c.begin(), calibration.temp_c.end(), 0.0) /
      static_cast<double>(calibration.temp_c.size());
  // The level's gradient over every value (zero but for the pick's own), by central differences.
  Eigen::VectorXd gradient = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(values.size()));
  for (std::size_t k : own) {
    const SearchRange& range = values[k].range;
    const double h = 1e-4 * (range.hi - range.lo);
    sim::ParamValues up = effect.params, down = effect.params;
    up[range.key] += h;
    down[range.key] -= h;
    gradient(static_cast<Eigen::Index>(k)) = (law->at(up, temp_c) - law->at(down, temp_c)) / (2 * h);
  }
  const double sensitivity = combination_sensitivity(gram, rows, gradient);
  const double resolution = sensitivity > 0.0
                                ? std::sqrt(criteria::kScoreResolution) * noise_v / sensitivity
                                : std::numeric_limits<double>::infinity();
  return EffectLevel{law->key, temp_c, law->at(effect.params, temp_c), resolution};
}

}  // namespace flange::diagnose
