// SPDX-License-Identifier: MIT
#include "locate.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "criteria.h"
#include "regions.h"
#include "series_arithmetic.h"
#include "stage_gaps.h"

namespace flange::diagnose {
namespace {

// The cell where the gap stands out most above the noise, among cells with enough samples.
std::optional<std::size_t> where_region(const std::vector<RegionCell>& regions, double sigma) {
  std::optional<std::size_t> where;
  double worst = 0.0;
  for (std::size_t k = 0; k < regions.size(); ++k) {
    const RegionCell& c = regions[k];
    const double excess = c.rms_v * c.rms_v - sigma * sigma;
    if (c.n >= criteria::kLeastSamplesPerCell && excess > worst) {
      worst = excess;
      where = k;
    }
  }
  return where;
}

// The gap's mean-square coherence with `input`, over the band (or every bin), and its peak.
InputCoherence coherence_with(const std::string& name, const std::vector<double>& gap,
                              const std::vector<double>& input, double fs_hz, std::size_t segment,
                              const std::optional<std::pair<double, double>>& band_hz) {
  const Spectrum msc = coherence(gap, input, fs_hz, segment);
  InputCoherence c{name, 0.0, 0.0, 0.0};
  int count = 0;
  for (std::size_t k = 1; k < msc.value.size(); ++k) {
    const double f = msc.frequency_hz[k];
    if (!band_hz || (f >= band_hz->first && f <= band_hz->second)) {
      c.in_band += msc.value[k];
      ++count;
    }
    if (msc.value[k] > c.peak) {
      c.peak = msc.value[k];
      c.peak_hz = f;
    }
  }
  if (count > 0) c.in_band /= count;
  return c;
}

}  // namespace

std::vector<double> rate_of(const std::vector<double>& t, const std::vector<double>& x) {
  std::vector<double> r(x.size(), 0.0);
  for (std::size_t i = 0; i < x.size(); ++i) {
    const std::size_t lo = i == 0 ? 0 : i - 1, hi = i + 1 == x.size() ? i : i + 1;
    if (hi > lo) r[i] = (x[hi] - x[lo]) / (t[hi] - t[lo]);
  }
  return r;
}

double band_rms(const Spectrum& psd, std::pair<double, double> band) {
  if (psd.frequency_hz.size() < 2) return 0.0;
  const double df = psd.frequency_hz[1] - psd.frequency_hz[0];
  double power = 0.0;
  for (std::size_t k = 0; k < psd.value.size(); ++k) {
    if (psd.frequency_hz[k] >= band.first - 1e-12 && psd.frequency_hz[k] <= band.second + 1e-12) {
      power += psd.value[k] * df;
    }
  }
  return std::sqrt(power);
}

std::optional<std::pair<double, double>> gap_band(const Spectrum& psd, double noise_psd) {
  const std::vector<double>& p = psd.value;
  std::size_t peak = 0;
  double peak_excess = 0.0;
  for (std::size_t k = 1; k < p.size(); ++k) {
    if (p[k] - noise_psd > peak_excess) {
      peak_excess = p[k] - noise_psd;
      peak = k;
    }
  }
  const double floor = criteria::kBandPsdRatio * noise_psd;
  if (peak == 0 || !(p[peak] > floor)) return std::nullopt;
  std::size_t lo = peak, hi = peak;
  while (lo > 1 && p[lo - 1] > floor) --lo;
  while (hi + 1 < p.size() && p[hi + 1] > floor) ++hi;
  return std::make_pair(psd.frequency_hz[lo], psd.frequency_hz[hi]);
}

Location locate(const RecordingSeries& cal, const std::vector<double>& sim_v, double fs_hz,
                const DiagnoseOptions& options, const TwinNoise& noise,
                const NullReplica& replica_of) {
  const double sigma = noise.noise_std_v;
  Location detail;
  detail.fs_hz = fs_hz;
  const std::vector<double> gap = minus(cal.voltage_v, sim_v);
  detail.t_s = cal.t_s;
  detail.gap_v = gap;
  detail.stages = stage_gaps(cal, sim_v, noise.white_noise, options.twin.nominal, fs_hz,
                             options.seed, replica_of);
  detail.regions =
      region_cells(cal, gap, region_grid_for(cal), options.bootstrap_rounds, options.seed);
  detail.where_region = where_region(detail.regions, sigma);
  const std::size_t segment = spectrum_segment(gap.size());
  detail.gap_psd = welch_psd(gap, fs_hz, segment);
  detail.noise_psd = 2.0 * sigma * sigma / fs_hz;
  detail.band_hz = gap_band(detail.gap_psd, detail.noise_psd);
  const std::vector<double> temp_rate = rate_of(cal.t_s, cal.temp_c);
  detail.coherences = {
      coherence_with("temperature", gap, cal.temp_c, fs_hz, segment, detail.band_hz),
      coherence_with("temperature_rate", gap, temp_rate, fs_hz, segment, detail.band_hz),
      coherence_with("clearance", gap, cal.clearance_mm, fs_hz, segment, detail.band_hz)};
  const std::size_t min_length = std::max<std::size_t>(30, gap.size() / 50);
  for (const MeanSegment& s : mean_change_points(gap, sigma, 0.5 * sigma, min_length, 8)) {
    detail.segments.push_back({cal.t_s[s.begin], cal.t_s[s.end - 1], s.mean});
  }
  const std::size_t lags = criteria::kResidualTestLags;
  detail.whiteness = whiteness_test(gap, lags);
  detail.vs_temperature = independence_test(gap, cal.temp_c, lags);
  detail.vs_temperature_rate = independence_test(gap, temp_rate, lags);
  detail.vs_clearance = independence_test(gap, cal.clearance_mm, lags);
  return detail;
}

}  // namespace flange::diagnose
