// SPDX-License-Identifier: MIT
#include "separate_sessions.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <system_error>
#include <vector>

#include "input_error.h"

namespace flange::diagnose {
namespace {

bool same_file(const std::string& a, const std::string& b) {
  if (a.empty() || b.empty()) return false;
  std::error_code error;
  const bool same = std::filesystem::equivalent(a, b, error);
  return !error && same;
}

bool same_rows(const RecordingSeries& a, const RecordingSeries& b) {
  return a.t_s == b.t_s && a.clearance_mm == b.clearance_mm && a.temp_c == b.temp_c &&
         a.voltage_v == b.voltage_v;
}

using Row = std::array<double, 4>;

Row row_of(const RecordingSeries& s, std::size_t i) {
  return {s.t_s[i], s.clearance_mm[i], s.temp_c[i], s.voltage_v[i]};
}

// How many of `heldout`'s rows appear, identical in every column, among `calibration`'s.
std::size_t rows_repeated(const RecordingSeries& calibration, const RecordingSeries& heldout) {
  std::vector<Row> known(calibration.size());
  for (std::size_t i = 0; i < calibration.size(); ++i) known[i] = row_of(calibration, i);
  std::sort(known.begin(), known.end());
  std::size_t repeated = 0;
  for (std::size_t i = 0; i < heldout.size(); ++i) {
    repeated += std::binary_search(known.begin(), known.end(), row_of(heldout, i)) ? 1 : 0;
  }
  return repeated;
}

std::string name_of(const RecordingSeries& series, const char* fallback) {
  return series.path.empty() ? fallback : series.path;
}

// Both start times given: the held-out span on the calibration's clock must not meet its span.
void check_start_times(const RecordingSeries& calibration, const RecordingSeries& heldout,
                       const std::string& cal, const std::string& ho) {
  const double cal_first = calibration.t_s.front(), cal_last = calibration.t_s.back();
  const double offset = *heldout.start_utc_s - *calibration.start_utc_s;
  const double ho_first = heldout.t_s.front() + offset, ho_last = heldout.t_s.back() + offset;
  if (ho_first <= cal_last && ho_last >= cal_first) {
    throw host::InputError(fmt::format(
        "--holdout-start: {} covers {:.6g} s to {:.6g} s of {}'s clock, inside its {:.6g} s "
        "to {:.6g} s; held-out data must not overlap the calibration session in time",
        ho, ho_first, ho_last, cal, cal_first, cal_last));
  }
}

}  // namespace

void check_separate_sessions(const RecordingSeries& calibration, const RecordingSeries& heldout) {
  const std::string cal = name_of(calibration, "the calibration part");
  const std::string ho = name_of(heldout, "the held-out part");
  if (same_file(calibration.path, heldout.path) || same_rows(calibration, heldout)) {
    throw host::InputError(fmt::format(
        "--holdout: {} is the same recording as --real {}; held-out data must be another session "
        "(or use --holdout-fraction)",
        ho, cal));
  }
  if (calibration.size() == 0 || heldout.size() == 0) return;
  if (calibration.start_utc_s && heldout.start_utc_s) {
    check_start_times(calibration, heldout, cal, ho);
    return;
  }
  const std::size_t repeated = rows_repeated(calibration, heldout);
  if (2 * repeated > heldout.size()) {
    throw host::InputError(fmt::format(
        "--holdout: {} of {}'s {} rows repeat rows of {} (time, clearance, temperature and "
        "voltage); held-out data must not overlap the calibration session in time",
        repeated, ho, heldout.size(), cal));
  }
}

}  // namespace flange::diagnose
