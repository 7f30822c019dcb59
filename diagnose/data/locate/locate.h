// SPDX-License-Identifier: MIT
// Where the gap lies on the calibration part: the stage where it first appears, the operating
// region, the frequency band, which inputs it is coherent with, the time segments of its mean,
// and the residual tests (docs/diagnose.md, "Locate").
#pragma once

#include <utility>
#include <vector>

#include "diagnosis.h"
#include "diagnosis_detail.h"
#include "null_replicas.h"
#include "recording_series.h"
#include "residual_tests.h"

namespace flange::diagnose {

// Fills detail's stages, regions, where_region, gap_psd, noise_psd, band_hz, coherences,
// segments and residual tests for the calibration part `cal` against the twin's `sim_v`, at the
// noise detail.noise_std_v, the stages' floors drawn by `replica_of` when set (null_replicas.h).
void locate(const RecordingSeries& cal, const std::vector<double>& sim_v, double fs_hz,
            const DiagnoseOptions& options, DiagnosisDetail& detail,
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
