// SPDX-License-Identifier: MIT
#include "hypothetical_session.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "criteria.h"

namespace flange::diagnose {
namespace {

constexpr std::size_t kMostRows = 8192;
constexpr double kLowestClearanceMm = criteria::kOperatingRangeLowestMm;
constexpr double kHighestClearanceMm = criteria::kOperatingRangeHighestMm;
// The clearance's up-and-down moves in an operating-range session.
constexpr double kClearanceSweepsOverTheRange = 20.0;

double mean_of(const std::vector<double>& v) {
  return std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
}

// 0 at the session's start and end, 1 in its middle.
double triangle(double t, double t0, double t1) {
  const double u = t1 > t0 ? (t - t0) / (t1 - t0) : 0.0;
  return u < 0.5 ? 2.0 * u : 2.0 - 2.0 * u;
}

// Every stride-th row of `calibration`, so that no more than kMostRows are kept.
std::size_t stride_of(const RecordingSeries& calibration) {
  return std::max<std::size_t>(1, (calibration.size() + kMostRows - 1) / kMostRows);
}

// A span's centre: `mean`, moved so that the span stays within [lowest, highest] where it fits.
double centre_within(double mean, double span, double lowest, double highest) {
  return std::clamp(mean, lowest + 0.5 * span, std::max(lowest + 0.5 * span, highest - 0.5 * span));
}

}  // namespace

SweepRange sweep_range(const RecordingSeries& calibration, const std::string& variable,
                       double span) {
  const bool temperature = variable == "temperature";
  const double centre =
      temperature ? centre_within(mean_of(calibration.temp_c), span,
                                  criteria::kOperatingRangeLowestC, criteria::kOperatingRangeHighestC)
                  : centre_within(mean_of(calibration.clearance_mm), span, kLowestClearanceMm,
                                  kHighestClearanceMm);
  return {centre - 0.5 * span, centre + 0.5 * span};
}

const std::vector<Sweep>& sweeps() {
  static const std::vector<Sweep> all = {
      {"temperature", "degC", {1, 2, 5, 10, 20, 40, 80}},
      {"clearance", "mm", {0.5, 1, 2, 4, 8}},
  };
  return all;
}

RecordingSeries hypothetical_session(const RecordingSeries& calibration,
                                     const std::string& variable, double span) {
  RecordingSeries out;
  out.path = "a session sweeping the " + variable;
  const std::size_t n = calibration.size();
  const std::size_t stride = stride_of(calibration);
  const double t0 = calibration.t_s.front(), t1 = calibration.t_s.back();
  const SweepRange range = sweep_range(calibration, variable, span);
  const double centre = 0.5 * (range.lowest + range.highest);
  for (std::size_t i = 0; i < n; i += stride) {
    const double t = calibration.t_s[i];
    const double swing = span * (triangle(t, t0, t1) - 0.5);
    out.t_s.push_back(t);
    const bool temperature = variable == "temperature";
    out.temp_c.push_back(temperature ? centre + swing : calibration.temp_c[i]);
    out.clearance_mm.push_back(temperature ? calibration.clearance_mm[i] : centre + swing);
    out.voltage_v.push_back(0.0);
  }
  out.start_utc_s = calibration.start_utc_s;
  return out;
}

RecordingSeries operating_range_session(const RecordingSeries& calibration) {
  RecordingSeries out;
  out.path = "a session over the bench's operating range";
  const double t0 = calibration.t_s.front(), t1 = calibration.t_s.back();
  const double cycle_s = (t1 - t0) / kClearanceSweepsOverTheRange;
  for (std::size_t i = 0; i < calibration.size(); i += stride_of(calibration)) {
    const double t = calibration.t_s[i];
    const double heat = triangle(t, t0, t1);
    const double u = cycle_s > 0.0 ? std::fmod(t - t0, cycle_s) : 0.0;
    out.t_s.push_back(t);
    out.temp_c.push_back(criteria::kOperatingRangeLowestC +
                         heat * (criteria::kOperatingRangeHighestC - criteria::kOperatingRangeLowestC));
    out.clearance_mm.push_back(kLowestClearanceMm +
                               triangle(u, 0.0, cycle_s) * (kHighestClearanceMm - kLowestClearanceMm));
    out.voltage_v.push_back(0.0);
  }
  out.start_utc_s = calibration.start_utc_s;
  return out;
}

}  // namespace flange::diagnose
