// SPDX-License-Identifier: MIT
// Where the gap lies on the calibration part: the stage where it first appears, the operating
// region, the frequency band, which inputs it is coherent with, the time segments of its mean,
// and the residual tests (docs/diagnose.md, "Locate").
#pragma once

#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

#include "diagnosis.h"
#include "findings.h"
#include "twin_noise.h"
#include "null_replicas.h"
#include "recording_series.h"
#include "series_statistics.h"

namespace flange::diagnose {

// The locate stage's value: where the gap lies on the calibration part.
struct Location {
  double fs_hz = 0.0;
  std::vector<StageGap> stages;
  std::vector<RegionCell> regions;
  std::optional<std::size_t> where_region;  // index into regions
  std::optional<std::pair<double, double>> band_hz;
  std::vector<InputCoherence> coherences;
  std::vector<TimeSegment> segments;
  CorrelationTest whiteness, vs_temperature, vs_clearance, vs_temperature_rate;
  Spectrum gap_psd;                // of the calibration voltage gap
  double noise_psd = 0.0;          // white-noise level for comparison, V^2/Hz
  std::vector<double> t_s, gap_v;  // the calibration voltage gap over time
};

// Where the gap of the calibration part `cal` against the twin's `sim_v` lies: its stages,
// regions, band, coherences, segments and residual tests at the twin's noise `noise`, the stages'
// floors drawn by `replica_of` when set (null_replicas.h).
Location locate(const RecordingSeries& cal, const std::vector<double>& sim_v, double fs_hz,
                const DiagnoseOptions& options, const TwinNoise& noise,
                const NullReplica& replica_of = {});

// The band: from the bin of largest excess over `noise_psd`, widened while the PSD stays above
// criteria::kBandPsdRatio times it; none when the peak is not that high. DC is left out (each
// segment's mean is removed).
std::optional<std::pair<double, double>> gap_band(const Spectrum& psd, double noise_psd);

// The RMS a PSD holds within `band` (Hz, both ends included).
double band_rms(const Spectrum& psd, std::pair<double, double> band);

// The rate of change of `x` over times `t` by central differences (one-sided at the ends).
std::vector<double> rate_of(const std::vector<double>& t, const std::vector<double>& x);

}  // namespace flange::diagnose
