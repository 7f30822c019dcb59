// SPDX-License-Identifier: MIT
#include "recording_series.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "input_error.h"
#include "recording_csv.h"

namespace flange::diagnose {

using host::InputError;

RecordingSeries read_recording_series(const std::string& path) {
  host::RecordingReader reader(path);
  RecordingSeries series;
  series.path = path;
  while (const std::optional<host::RecordingRow> row = reader.next()) {
    if (!row->clearance_mm) {
      throw InputError(fmt::format(
          "{}:{}: clearance_mm: empty; diagnose needs the reference clearance on every row (a "
          "number in mm)",
          path, row->line));
    }
    if (!series.t_s.empty() && row->t_s <= series.t_s.back()) {
      throw InputError(
          fmt::format("{}:{}: t_s: {} does not increase (a run column's restart "
                      "cannot be diagnosed as one series)",
                      path, row->line, row->t_s));
    }
    series.t_s.push_back(row->t_s);
    series.clearance_mm.push_back(*row->clearance_mm);
    series.temp_c.push_back(row->temp_c);
    series.voltage_v.push_back(row->voltage_v);
  }
  return series;
}

RecordingSeries slice_recording_series(const RecordingSeries& series, std::size_t begin,
                                       std::size_t end, const std::string& label) {
  RecordingSeries part;
  part.path = label;
  const auto cut = [&](const std::vector<double>& v) {
    return std::vector<double>(v.begin() + static_cast<long>(begin),
                               v.begin() + static_cast<long>(end));
  };
  part.t_s = cut(series.t_s);
  part.clearance_mm = cut(series.clearance_mm);
  part.temp_c = cut(series.temp_c);
  part.voltage_v = cut(series.voltage_v);
  part.start_utc_s = series.start_utc_s;  // the same clock: t_s is kept as it was
  return part;
}

HoldoutSplit split_holdout(const RecordingSeries& real, double fraction) {
  const auto held =
      static_cast<std::size_t>(std::floor(fraction * static_cast<double>(real.size())));
  constexpr std::size_t kMinPart = 256;
  if (held < kMinPart || real.size() - held < kMinPart) {
    throw InputError(fmt::format(
        "{}: {} rows are too short to hold out {}: each part needs at least {} rows (the "
        "recording needs at least {} rows at this fraction)",
        real.path, real.size(), fraction, kMinPart,
        static_cast<std::size_t>(std::ceil(kMinPart / std::min(fraction, 1.0 - fraction)))));
  }
  HoldoutSplit split;
  split.calibration =
      slice_recording_series(real, 0, real.size() - held, real.path + " (calibration part)");
  split.heldout =
      slice_recording_series(real, real.size() - held, real.size(), real.path + " (held-out part)");
  split.heldout_name = fmt::format("last {} of {}", fraction, real.path);
  return split;
}

std::vector<bool> pairs_at_rest(const std::vector<double>& clearance_mm) {
  constexpr double kMovingMm = 1e-4;  // a sample-to-sample change that is a move
  constexpr double kLeastRestShare = 0.25;
  const std::size_t n = clearance_mm.size();
  if (n < 2) return {};
  std::vector<bool> rest(n - 1);
  std::size_t resting = 0;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    rest[i] = std::abs(clearance_mm[i + 1] - clearance_mm[i]) <= kMovingMm;
    resting += rest[i] ? 1 : 0;
  }
  if (static_cast<double>(resting) < kLeastRestShare * static_cast<double>(n - 1)) return {};
  return rest;
}

}  // namespace flange::diagnose
