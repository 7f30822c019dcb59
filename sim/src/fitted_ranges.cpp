// SPDX-License-Identifier: MIT
#include "fitted_ranges.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace flange::sim {
namespace {

std::string range_problem(const char* field, double lo, double hi, double min, double max,
                          const char* unit) {
  if (std::isfinite(lo) && std::isfinite(hi) && lo >= min && lo <= hi && hi <= max) return "";
  return fmt::format("{}: [{}, {}] is not a range [low, high] with {} <= low <= high <= {} {}",
                     field, lo, hi, min, max, unit);
}

}  // namespace

std::string fitted_ranges_problem(const FittedRanges& r) {
  std::string problem = range_problem("clearance_mm", r.clearance_lo_mm, r.clearance_hi_mm, 0.0,
                                      kFittedClearanceMaxMm, "mm");
  if (problem.empty()) {
    problem = range_problem("temperature_c", r.temperature_lo_c, r.temperature_hi_c,
                            kFittedTemperatureMinC, kFittedTemperatureMaxC, "degC");
  }
  return problem;
}

std::optional<FittedRanges> overlap(const FittedRanges& a, const FittedRanges& b) {
  const FittedRanges both{std::max(a.clearance_lo_mm, b.clearance_lo_mm),
                          std::min(a.clearance_hi_mm, b.clearance_hi_mm),
                          std::max(a.temperature_lo_c, b.temperature_lo_c),
                          std::min(a.temperature_hi_c, b.temperature_hi_c)};
  if (both.clearance_lo_mm > both.clearance_hi_mm || both.temperature_lo_c > both.temperature_hi_c)
    return std::nullopt;
  return both;
}

}  // namespace flange::sim
