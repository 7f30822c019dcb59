// SPDX-License-Identifier: MIT
#include "sample_rate.h"

#include <fmt/format.h>

#include <cmath>
#include <string>
#include <vector>

#include "criteria.h"
#include "input_error.h"
#include "series_arithmetic.h"

namespace flange::diagnose {
namespace {

using host::InputError;

void check_series(const RecordingSeries& s, const std::string& role) {
  const std::string name = s.path.empty() ? role : s.path;
  if (s.size() < criteria::kLeastSamplesPerPart) {
    throw InputError(fmt::format("{}: {} rows in the {} part; at least {} are needed", name,
                                 s.size(), role, criteria::kLeastSamplesPerPart));
  }
  if (s.clearance_mm.size() != s.size() || s.temp_c.size() != s.size() ||
      s.voltage_v.size() != s.size()) {
    throw InputError(fmt::format("{}: columns of unequal length", name));
  }
}

}  // namespace

double sample_rate_hz(const RecordingSeries& series) {
  if (series.size() < 2) {
    throw InputError(fmt::format("{}: fewer than 2 rows: no sample rate", series.path));
  }
  for (std::size_t i = 1; i < series.size(); ++i) {
    if (!(series.t_s[i] - series.t_s[i - 1] > 0.0)) {
      throw InputError(fmt::format("{}: row {}: t_s = {} does not increase (previous {})",
                                   series.path, i + 1, series.t_s[i], series.t_s[i - 1]));
    }
  }
  return rate_of_median_step(series.t_s);
}

double shared_sample_rate_hz(const RecordingSeries& calibration, const RecordingSeries& heldout) {
  check_series(calibration, "calibration");
  check_series(heldout, "held-out");
  const double fs_hz = sample_rate_hz(calibration);
  const double fs_heldout = sample_rate_hz(heldout);
  if (std::abs(fs_heldout - fs_hz) > criteria::kSampleRateAgreement * fs_hz) {
    throw InputError(fmt::format(
        "{}: sample rate {:.6g} Hz differs from {}'s {:.6g} Hz; the held-out recording must be "
        "sampled at the same rate (within 1 %)",
        heldout.path.empty() ? "held-out" : heldout.path, fs_heldout,
        calibration.path.empty() ? "the calibration part" : calibration.path, fs_hz));
  }
  return fs_hz;
}

}  // namespace flange::diagnose
