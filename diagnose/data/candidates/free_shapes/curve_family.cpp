// SPDX-License-Identifier: MIT
#include "curve_family.h"

#include <fmt/format.h>

#include "family_makers.h"
#include "ridge_solve.h"
#include "sensor_age.h"

namespace flange::diagnose::free_shapes {
namespace {

// Knots of a curve of clearance: about a third of a millimetre apart over the thesis's 1-9 mm,
// six or more to the period of a 2 mm ripple (a piecewise-linear curve's error on a sine falls as
// the square of its knot spacing over the period).
constexpr int kClearanceKnots = 25;
// How far a curve of clearance may go on along its end segments beyond the calibration part's
// range, in mm, before it is held: a held-out session whose micrometer travels further (half a
// millimetre past 2 mm) meets a characteristic error that a smooth one (the library's polynomial
// of voltage too) continues, and a ripple does not. Which of the two each end is, the calibration
// part says (choose_reach).
constexpr double kClearanceReachMm = 1.0;
// Knots of a trend in the sensor's age over the calibration session (held at its last value
// after it: a step or a settling that has ended): nine, an eighth of the session apart. The curve
// follows a step as a ramp one spacing wide, so the last knot, the value held after the session,
// reaches the step's full height unless the step lies in the session's last eighth.
constexpr int kAgeKnots = 9;

}  // namespace

CurveFamily::CurveFamily(CurveOf of, const RecordedPart& calibration, int knots) : of_(of) {
  switch (of_) {
    case CurveOf::kVoltage:
      hats_ = hats_over(calibration.replay.nominal_voltage(), kKnots);
      for (std::size_t k = 1; k + 1 < kKnots; ++k) used_.push_back(k);  // 0 at both ends
      break;
    case CurveOf::kClearance:
      hats_ = hats_over(calibration.series.clearance_mm, kClearanceKnots);
      for (std::size_t k = 0; k < kClearanceKnots; ++k) used_.push_back(k);
      break;
    case CurveOf::kAge:
      hats_ = hats_over(age_days(calibration), kAgeKnots);
      for (std::size_t k = 0; k < kAgeKnots; ++k) used_.push_back(k);
      break;
    case CurveOf::kTemperature:
    case CurveOf::kGainOfTemperature:
      hats_ = hats_over(calibration.series.temp_c, knots);
      hats_.reach_both(kTemperatureReach * (knots - 1) / (kKnots - 1));  // the same degC
      for (std::size_t k = 0; k < static_cast<std::size_t>(knots); ++k) used_.push_back(k);
      break;
  }
}

void CurveFamily::search(const RecordedPart& calibration, const std::vector<double>& gap_v) {
  const auto columns_with = [&](const Hats& hats) {
    CurveFamily with = *this;
    with.hats_ = hats;
    return with.columns(calibration);
  };
  if (of_ == CurveOf::kClearance) {
    choose_reach(hats_, calibration.series.clearance_mm, gap_v, kClearanceReachMm, 0.0,
                 kClearanceReachMm, columns_with);
  } else if (of_ == CurveOf::kTemperature || of_ == CurveOf::kGainOfTemperature) {
    choose_temperature_reach(hats_, calibration, gap_v, columns_with);
  }
}

std::vector<std::string> CurveFamily::names() const {
  std::vector<std::string> out;
  const char* unit = of_ == CurveOf::kVoltage     ? "v"
                     : of_ == CurveOf::kClearance ? "mm"
                     : of_ == CurveOf::kAge       ? "d"
                                                  : "c";
  for (std::size_t k : used_) {
    out.push_back(fmt::format("{}_at_{:.4g}{}",
                              of_ == CurveOf::kGainOfTemperature ? "gain_change" : "offset_v",
                              hats_.knots[k], unit));
  }
  return out;
}

double CurveFamily::variable_at(const RecordedPart& part, const std::vector<double>& age,
                                std::size_t i) const {
  switch (of_) {
    case CurveOf::kVoltage:
      return part.replay.nominal_voltage()[i];
    case CurveOf::kClearance:
      return part.series.clearance_mm[i];
    case CurveOf::kAge:
      return age[i];
    case CurveOf::kTemperature:
    case CurveOf::kGainOfTemperature:
      break;
  }
  return part.series.temp_c[i];
}

Eigen::MatrixXd CurveFamily::columns(const RecordedPart& part) const {
  const std::size_t n = part.series.size();
  Eigen::MatrixXd a = matrix(n, used_.size());
  const std::vector<double> age = of_ == CurveOf::kAge ? age_days(part) : std::vector<double>{};
  // The column of each knot (used_ holds the knots in increasing order), -1 where unused.
  std::vector<long> column_of(hats_.knots.size(), -1);
  for (std::size_t j = 0; j < used_.size(); ++j) column_of[used_[j]] = static_cast<long>(j);
  for (std::size_t i = 0; i < n; ++i) {
    const double v = part.replay.nominal_voltage()[i];
    const double x = variable_at(part, age, i);
    const double scale = of_ == CurveOf::kGainOfTemperature ? v - part.replay.v_min_v() : 1.0;
    const auto row = static_cast<Eigen::Index>(i);
    // Off the hats' support a weight is +0.0, and the column scale * +0.0 (-0.0 for a negative
    // scale): only the knots around x are weighed.
    if (std::signbit(scale)) a.row(row).setConstant(scale * 0.0);
    const auto [first, last] = hats_.support(x);
    for (std::size_t k = first; k <= last; ++k) {
      if (column_of[k] >= 0) a(row, column_of[k]) = scale * hats_.weight(k, x);
    }
  }
  return a;
}

std::string CurveFamily::describe(const Eigen::VectorXd& beta) const {
  const char* what = of_ == CurveOf::kGainOfTemperature ? "T (a gain about v_min)"
                     : of_ == CurveOf::kClearance       ? "the clearance"
                     : of_ == CurveOf::kAge     ? "the sensor's age, settled after the session"
                     : of_ == CurveOf::kVoltage ? "V"
                                                : "T";
  const char* unit = of_ == CurveOf::kVoltage     ? "V"
                     : of_ == CurveOf::kClearance ? "mm"
                     : of_ == CurveOf::kAge       ? "days"
                                                  : "degC";
  std::string text = fmt::format("a free curve of {} through", what);
  for (std::size_t j = 0; j < used_.size(); ++j) {
    text += fmt::format("{} {:.3g} at {:.4g} {}", j == 0 ? "" : ",",
                        beta(static_cast<Eigen::Index>(j)), hats_.knots[used_[j]], unit);
  }
  return text;
}

std::unique_ptr<Family> make_temperature_offset_curve(const RecordedPart& calibration) {
  return std::make_unique<CurveFamily>(CurveOf::kTemperature, calibration);
}
std::unique_ptr<Family> make_temperature_gain_curve(const RecordedPart& calibration) {
  return std::make_unique<CurveFamily>(CurveOf::kGainOfTemperature, calibration);
}
std::unique_ptr<Family> make_fine_temperature_offset_curve(const RecordedPart& calibration) {
  return std::make_unique<CurveFamily>(CurveOf::kTemperature, calibration, kFineKnots);
}
std::unique_ptr<Family> make_fine_temperature_gain_curve(const RecordedPart& calibration) {
  return std::make_unique<CurveFamily>(CurveOf::kGainOfTemperature, calibration, kFineKnots);
}
std::unique_ptr<Family> make_voltage_curve(const RecordedPart& calibration) {
  return std::make_unique<CurveFamily>(CurveOf::kVoltage, calibration);
}
std::unique_ptr<Family> make_clearance_curve(const RecordedPart& calibration) {
  return std::make_unique<CurveFamily>(CurveOf::kClearance, calibration);
}
std::unique_ptr<Family> make_settled_age_curve(const RecordedPart& calibration) {
  return std::make_unique<CurveFamily>(CurveOf::kAge, calibration);
}

}  // namespace flange::diagnose::free_shapes
