// SPDX-License-Identifier: MIT
#include "history_mean_rate.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace flange::host {
namespace {

// E_j: the odometer at the first run of each piece after the first.
std::vector<double> piece_starts(const WearSeries& series, int pieces) {
  const double first = series.day.front(), span = series.day.back() - first;
  std::vector<double> starts;
  int piece = 0;
  for (std::size_t k = 0; k < series.day.size(); ++k) {
    const int at = std::min(pieces - 1, static_cast<int>((series.day[k] - first) / span * pieces));
    if (at > piece) {
      starts.push_back(series.km[k]);
      piece = at;
    }
  }
  return starts;
}

// The rise of the fitted line from `km_first` to `km_last` over the km between; throws
// std::invalid_argument when the fit leaves a parameter free.
double history_rise(const WearSeries& series, const std::vector<double>& starts, double km_first,
                    double km_last, WearLineFit* fit_out = nullptr, double* se_out = nullptr) {
  const WearLineFit fit = fit_wear_line(series, std::nullopt);
  if (!fit.full_rank) throw std::invalid_argument("history_rise: a piece without runs");
  // The parameters in fit_wear_line's order: the intercepts, the rate, the shared regressors
  // (the ramps' slope changes last).
  const std::size_t rate = fit.intercepts_mm.size();
  const std::size_t first_ramp = fit.shared_coefficients.size() - starts.size();
  std::vector<double> contrast(fit.covariance.size(), 0.0);
  contrast[rate] = 1.0;
  double rise = fit.rate_mm_per_km;
  for (std::size_t j = 0; j < starts.size(); ++j) {
    const double weight = (km_last - starts[j]) / (km_last - km_first);
    contrast[rate + 1 + first_ramp + j] = weight;
    rise += fit.shared_coefficients[first_ramp + j] * weight;
  }
  const auto& cov = fit.covariance;
  if (se_out != nullptr) {
    double variance = 0.0;
    for (std::size_t a = 0; a < contrast.size(); ++a) {
      for (std::size_t b = 0; b < contrast.size(); ++b) {
        variance += contrast[a] * contrast[b] * cov[a][b];
      }
    }
    *se_out = std::sqrt(std::max(0.0, variance));
  }
  if (fit_out != nullptr) *fit_out = fit;
  return rise;
}

}  // namespace

std::optional<HistoryMeanFit> history_mean_fit(const WearSeries& series) {
  const double span = series.day.back() - series.day.front();
  const double km_first = series.km.front(), km_last = series.km.back();
  if (!(span > 0.0) || !(km_last > km_first)) return std::nullopt;
  HistoryMeanFit history;
  history.pieces = std::max(1, static_cast<int>(std::lround(span / kRatePieceDays)));
  const std::vector<double> starts = piece_starts(series, history.pieces);
  history.series = series;
  for (const double start : starts) {
    std::vector<double> ramp;
    for (const double km : series.km) ramp.push_back(std::max(0.0, km - start));
    history.series.shared.push_back(std::move(ramp));
  }
  try {
    history.rate_mm_per_km =
        history_rise(history.series, starts, km_first, km_last, &history.fit, &history.rate_se);
  } catch (const std::invalid_argument&) {
    return std::nullopt;
  }
  const int blocks = kBlocksPerPiece * history.pieces;
  const std::optional<JackknifeVariance> jackknife = block_jackknife(
      history.series, blocks,
      [&](const WearSeries& kept) { return history_rise(kept, starts, km_first, km_last); });
  // Without its jackknife the rise would carry the runs' own scatter alone: the line, whose
  // slope falls back the same way, is no narrower for it.
  if (!jackknife || !(history.rate_se > 0.0)) return std::nullopt;
  history.own_spread = {std::sqrt(jackknife->variance),
                        jackknife->variance / (history.rate_se * history.rate_se), jackknife->dof,
                        blocks};
  return history;
}

double history_fit_at(const HistoryMeanFit& history, std::size_t k) {
  const WearSeries& series = history.series;
  const WearLineFit& fit = history.fit;
  double value = fit.intercepts_mm.at(static_cast<std::size_t>(series.segment.at(k))) +
                 fit.rate_mm_per_km * (series.km.at(k) - fit.km0);
  for (std::size_t j = 0; j < series.shared.size(); ++j) {
    value += fit.shared_coefficients[j] * series.shared[j][k];
  }
  return value;
}

}  // namespace flange::host
