// SPDX-License-Identifier: MIT
#include "block_jackknife.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

namespace flange::host {
namespace {

// `series` without the runs of stretch `left_out`; segments renumbered 0, 1, ... over what
// remains (a flange wholly inside the stretch drops out).
WearSeries without_block(const WearSeries& series, const std::vector<int>& block, int left_out) {
  WearSeries kept;
  std::map<int, int> renumbered;
  for (std::size_t k = 0; k < series.y.size(); ++k) {
    if (block[k] == left_out) continue;
    kept.km.push_back(series.km[k]);
    kept.day.push_back(series.day[k]);
    kept.y.push_back(series.y[k]);
    const int segment = series.segment.empty() ? 0 : series.segment[k];
    kept.segment.push_back(
        renumbered.emplace(segment, static_cast<int>(renumbered.size())).first->second);
    if (!series.drift_scale.empty()) kept.drift_scale.push_back(series.drift_scale[k]);
  }
  for (const std::vector<double>& column : series.shared) {
    std::vector<double> kept_column;
    for (std::size_t k = 0; k < column.size(); ++k) {
      if (block[k] != left_out) kept_column.push_back(column[k]);
    }
    kept.shared.push_back(std::move(kept_column));
  }
  return kept;
}

}  // namespace

int jackknife_blocks(double span_days, double block_days) {
  return std::clamp(static_cast<int>(std::lround(span_days / block_days)), kMinBlocks, kMaxBlocks);
}

std::optional<JackknifeVariance> block_jackknife(
    const WearSeries& series, int blocks,
    const std::function<double(const WearSeries&)>& statistic) {
  const double first = series.day.front(), span = series.day.back() - first;
  if (!(span > 0.0) || blocks < 2) return std::nullopt;
  std::vector<int> block;
  for (const double day : series.day) {
    block.push_back(std::min(blocks - 1, static_cast<int>((day - first) / span * blocks)));
  }
  std::vector<double> values;
  for (int b = 0; b < blocks; ++b) {
    try {
      values.push_back(statistic(without_block(series, block, b)));
    } catch (const std::invalid_argument&) {
      return std::nullopt;  // a stretch holds too much of the history
    }
  }
  double mean = 0.0;
  for (const double v : values) mean += v;
  mean /= blocks;
  double variance = 0.0;
  for (const double v : values) variance += (v - mean) * (v - mean);
  return JackknifeVariance{variance * (static_cast<double>(blocks - 1) / blocks), blocks - 1};
}

SerialSpread jackknife_rate(const WearSeries& series, std::optional<double> drift_onset_day,
                            int drift_degree, const WearLineFit& fit, double block_days) {
  SerialSpread spread{fit.rate_se, 1.0, fit.dof, 0};
  const double span = series.day.back() - series.day.front();
  if (!(span > 0.0)) return spread;
  const int blocks = jackknife_blocks(span, block_days);
  const std::optional<JackknifeVariance> jackknife =
      block_jackknife(series, blocks, [&](const WearSeries& kept) {
        // A drift needs runs after its onset in what is kept to be fitted at all.
        const bool drift_kept =
            drift_onset_day && !kept.day.empty() && kept.day.back() > *drift_onset_day;
        return fit_wear_line(kept, drift_kept ? drift_onset_day : std::nullopt, drift_degree)
            .rate_mm_per_km;
      });
  if (!jackknife) return spread;
  spread.rate_se = std::sqrt(jackknife->variance);
  spread.inflation =
      fit.rate_se > 0.0 ? jackknife->variance / (fit.rate_se * fit.rate_se) : 1.0;
  spread.dof = jackknife->dof;
  spread.blocks = blocks;
  return spread;
}

}  // namespace flange::host
