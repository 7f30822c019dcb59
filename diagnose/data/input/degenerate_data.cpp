// SPDX-License-Identifier: MIT
#include "degenerate_data.h"

#include <fmt/format.h>

#include <algorithm>

#include "criteria.h"

namespace flange::diagnose {
namespace {

std::vector<double> distinct(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  return values;
}

// One sentence for a variable with too few distinct values; returns whether it is constant.
bool judge(const std::vector<double>& values, const char* what, const char* unit,
           std::vector<std::string>& sentences) {
  const std::vector<double> seen = distinct(values);
  if (seen.size() == 1) {
    sentences.push_back(
        fmt::format("the {} is constant at {:.6g} {} in the calibration part: "
                    "nothing in the data follows it",
                    what, seen.front(), unit));
    return true;
  }
  if (!seen.empty() && seen.size() < criteria::kLeastDistinctValues) {
    sentences.push_back(fmt::format(
        "the {} takes only {} distinct values in the calibration part ({:.6g} to {:.6g} {}): a "
        "law of it cannot be told from a line through them",
        what, seen.size(), seen.front(), seen.back(), unit));
  }
  return false;
}

}  // namespace

DegenerateData degenerate_data(const RecordingSeries& calibration, double noise_std_v) {
  DegenerateData d;
  d.clearance_constant = judge(calibration.clearance_mm, "clearance", "mm", d.sentences);
  d.temperature_constant = judge(calibration.temp_c, "temperature", "degC", d.sentences);
  d.voltage_constant = judge(calibration.voltage_v, "voltage", "V", d.sentences);
  if (noise_std_v <= 0.0) {
    d.noise_zero = true;
    d.sentences.push_back(
        "the noise estimate is zero (the recorded voltage repeats to its last decimal): held-out "
        "scores are compared at the fits' own precision, and the gap has no structure in time or "
        "frequency to locate");
  }
  return d;
}

}  // namespace flange::diagnose
