// SPDX-License-Identifier: MIT
#include "white_noise.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "quantised_noise.h"
#include "series_statistics.h"

namespace flange::diagnose {
namespace {

// The median-based estimate differences at lag 2: as free of slow bias as lag 1, and unbiased
// also when neighbouring samples share noise (a channel interpolated by a skew).
constexpr std::size_t kNoiseLag = 2;
// A grid whose LSB is below an eighth of the noise adds under 0.1 % to its variance and the
// median's lattice bias is below 1 %: the grid is left out of the estimate.
constexpr double kCoarseLsbOverNoise = 1.0 / 8.0;

// A tone (mains pickup aliased by the sampling) inflates the lag-2 differences by up to twice
// its power, and a strong one makes their median read the tone, not the noise. The median of the
// Welch PSD over the upper three quarters of the band ignores the few bins a tone's lines take:
// when it reads below this share of the median-based estimate, the data hold a tone, and the
// PSD's level is the noise. On white noise the two agree within a few per cent.
constexpr double kToneRatio = 0.7;

// The white level of the upper three quarters of the band as a standard deviation (a one-sided
// PSD at fs = 1 is 2 sigma^2 for white noise).
double spectral_noise_std(const std::vector<double>& gap) {
  if (gap.size() < 256) return std::numeric_limits<double>::infinity();
  const Spectrum psd = welch_psd(gap, 1.0, spectrum_segment(gap.size()));
  std::vector<double> upper;
  for (std::size_t k = 0; k < psd.value.size(); ++k) {
    if (psd.frequency_hz[k] >= 0.125) upper.push_back(psd.value[k]);
  }
  if (upper.empty()) return std::numeric_limits<double>::infinity();
  std::nth_element(upper.begin(), upper.begin() + static_cast<std::ptrdiff_t>(upper.size() / 2),
                   upper.end());
  return std::sqrt(upper[upper.size() / 2] / 2.0);
}

double quantisation_variance(const std::optional<AdcGrid>& grid) {
  return grid ? grid->lsb_v * grid->lsb_v / 12.0 : 0.0;
}

}  // namespace

double WhiteNoise::noisy(double twin_v, double standard_normal) const {
  const double v = twin_v + analog_std_v * standard_normal;
  return grid ? grid->quantise(v) : v;
}

double WhiteNoise::quantised_null_rms() const {
  return grid ? diagnose::quantised_null_rms(analog_std_v, grid->lsb_v) : effective_std_v;
}

WhiteNoise estimate_white_noise(const std::vector<double>& recorded_v,
                                const std::vector<double>& twin_v,
                                const std::optional<AdcGrid>& grid) {
  std::vector<double> gap(recorded_v.size());
  for (std::size_t i = 0; i < gap.size(); ++i) gap[i] = recorded_v[i] - twin_v[i];
  WhiteNoise noise;
  noise.grid = grid;
  const double median_based = white_noise_std(gap, kNoiseLag);
  noise.grid_aware = grid && grid->lsb_v >= kCoarseLsbOverNoise * median_based;
  if (noise.grid_aware) {
    noise.analog_std_v = quantised_noise_std(recorded_v, twin_v, *grid, kNoiseLag);
    noise.effective_std_v =
        std::sqrt(noise.analog_std_v * noise.analog_std_v + quantisation_variance(grid));
    noise.source = fmt::format(
        "estimated on the {:.4g} mV converter grid: the maximum-likelihood fit of the code steps "
        "at lag 2 given the twin's (analog noise), with the grid's LSB^2/12 added",
        1e3 * grid->lsb_v);
  } else {
    const double spectral = spectral_noise_std(gap);
    const bool tone = spectral < kToneRatio * median_based;
    noise.effective_std_v = tone ? spectral : median_based;
    noise.analog_std_v = std::sqrt(
        std::max(0.0, noise.effective_std_v * noise.effective_std_v - quantisation_variance(grid)));
    noise.source =
        tone ? fmt::format(
                   "estimated from the gap's PSD: the median level above fs/8 (the differences' "
                   "median reads {:.4g} V, inflated by a tone)",
                   median_based)
             : "estimated from the gap: 1.4826 MAD(differences at lag 2) / sqrt(2)";
  }
  return noise;
}

WhiteNoise given_white_noise(double analog_std_v, const std::optional<AdcGrid>& grid) {
  WhiteNoise noise;
  noise.grid = grid;
  noise.analog_std_v = analog_std_v;
  noise.effective_std_v = std::sqrt(analog_std_v * analog_std_v + quantisation_variance(grid));
  noise.source = grid ? "given by the twin (noise.voltage_std_v), with the converter grid's "
                        "LSB^2/12 added"
                      : "given by the twin (noise.voltage_std_v)";
  return noise;
}

}  // namespace flange::diagnose
