// SPDX-License-Identifier: MIT
#include "thesis_pipeline.h"

#include <array>
#include <cmath>
#include <deque>

#include "calibration.h"
#include "recording_csv.h"

namespace flange::host {

namespace {

// Eq. 4.15 as printed.
constexpr std::array<double, 6> kB = {0.001076, 0.005379, 0.01076, 0.01076, 0.005379, 0.001076};
constexpr std::array<double, 6> kA = {1.0, -3.06, 3.997, -2.721, 0.9566, -0.138};

}  // namespace

ThesisPipelineResult run_thesis_pipeline(const std::string& recording_csv,
                                         std::uint64_t settle_samples) {
  ThesisPipelineResult result;
  double sum_b = 0.0, sum_a = 0.0, moment_b = 0.0, moment_a = 0.0;
  for (std::size_t n = 0; n < kB.size(); ++n) {
    sum_b += kB[n];
    sum_a += kA[n];
    moment_b += static_cast<double>(n) * kB[n];
    moment_a += static_cast<double>(n) * kA[n];
  }
  result.dc_gain = sum_b / sum_a;
  result.delay_samples = static_cast<int>(std::lround(moment_b / sum_b - moment_a / sum_a));

  RecordingReader reader(recording_csv);
  std::array<double, 6> x{}, y{};  // newest first
  std::deque<double> references;
  std::uint64_t rows = 0;
  while (const std::optional<RecordingRow> row = reader.next()) {
    const double d = eq_3_14(row->voltage_v, row->temp_c);
    // Direct form I from a zero state, as the thesis's LabVIEW/Simulink filter.
    for (std::size_t n = x.size() - 1; n > 0; --n) x[n] = x[n - 1];
    x[0] = d;
    double out = 0.0;
    for (std::size_t n = 0; n < kB.size(); ++n) out += kB[n] * x[n];
    for (std::size_t n = 1; n < kA.size(); ++n) out -= kA[n] * y[n - 1];
    for (std::size_t n = y.size() - 1; n > 0; --n) y[n] = y[n - 1];
    y[0] = out;
    ++rows;
    const double reference = row->clearance_mm.value_or(std::nan(""));
    if (!std::isnan(reference)) result.before.add(d - reference);
    references.push_back(reference);
    if (references.size() > static_cast<std::size_t>(result.delay_samples) + 1) {
      references.pop_front();
    }
    if (references.size() == static_cast<std::size_t>(result.delay_samples) + 1 &&
        !std::isnan(references.front()) && rows > settle_samples) {
      result.after.add(out - references.front());
    }
  }
  return result;
}

}  // namespace flange::host
