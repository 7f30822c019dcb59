// SPDX-License-Identifier: MIT
// The nominal model: eq. 3.14 inverted exactly, clipping outside the range, and any calibration
// polynomial (higher order, non-monotone) serving in its place.
#include "polynomial_sensor_model.h"

#include <gtest/gtest.h>

#include <cmath>

#include "sim_error.h"

namespace flange::sim {
namespace {

// Eq. 3.14 solved for V with the quadratic formula: an independent route to the same root.
double eq_3_14_voltage(double d_mm, double t_c) {
  const double a = 0.05812;
  const double b = 0.3672 + 0.0006618 * t_c;
  const double c = 1.16 - 0.0036 * t_c - d_mm;
  return (-b + std::sqrt(b * b - 4.0 * a * c)) / (2.0 * a);
}

TEST(PolynomialSensorModel, Eq314MatchesTheThesisCoefficients) {
  const PolynomialSensorModel model = PolynomialSensorModel::thesis_eq_3_14();
  const double v = 6.0;
  const double t = 70.0;
  EXPECT_DOUBLE_EQ(model.clearance_mm(v, t),
                   1.16 + 0.3672 * v - 0.0036 * t + 0.05812 * v * v + 0.0006618 * v * t);
  EXPECT_TRUE(model.monotone_in_voltage());
}

TEST(PolynomialSensorModel, InversionRoundTripsEq314To1e9MmAcrossRangeAndTemperatures) {
  const PolynomialSensorModel model = PolynomialSensorModel::thesis_eq_3_14();
  for (const double t_c : {-20.0, 0.0, 19.4, 20.0, 48.0, 73.0, 79.0, 92.0, 98.0, 120.0}) {
    const double d_low = model.clearance_mm(0.0, t_c);
    const double d_high = model.clearance_mm(10.0, t_c);
    constexpr int kPoints = 2000;
    for (int k = 0; k <= kPoints; ++k) {
      const double d = d_low + (d_high - d_low) * k / kPoints;
      const VoltageSolution solution = model.voltage_for(d, t_c);
      ASSERT_EQ(solution.clip, RailClip::kNone) << "d " << d << " T " << t_c;
      ASSERT_NEAR(model.clearance_mm(solution.volts, t_c), d, 1e-9) << "d " << d << " T " << t_c;
      ASSERT_NEAR(solution.volts, eq_3_14_voltage(d, t_c), 1e-9) << "d " << d << " T " << t_c;
    }
  }
}

TEST(PolynomialSensorModel, ValidRangeIsAbout1p1To10p7MmAtRoomTemperature) {
  const PolynomialSensorModel model = PolynomialSensorModel::thesis_eq_3_14();
  EXPECT_NEAR(model.clearance_mm(0.0, 20.0), 1.088, 1e-9);
  EXPECT_NEAR(model.clearance_mm(10.0, 20.0), 10.70436, 1e-9);
}

TEST(PolynomialSensorModel, ClearanceOutsideTheRangeClipsToARailAndSaysWhich) {
  const PolynomialSensorModel model = PolynomialSensorModel::thesis_eq_3_14();
  const VoltageSolution too_close = model.voltage_for(0.5, 20.0);
  EXPECT_EQ(too_close.volts, 0.0);
  EXPECT_EQ(too_close.clip, RailClip::kLow);
  const VoltageSolution too_far = model.voltage_for(12.0, 98.0);
  EXPECT_EQ(too_far.volts, 10.0);
  EXPECT_EQ(too_far.clip, RailClip::kHigh);
  // At 98 degC the bottom of the range moves down to 0.807 mm: 1.0 mm is still measurable.
  EXPECT_EQ(model.voltage_for(1.0, 98.0).clip, RailClip::kNone);
  EXPECT_EQ(model.voltage_for(1.0, 20.0).clip, RailClip::kLow);
}

TEST(PolynomialSensorModel, ThirdOrderCalibrationInvertsToo) {
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(4, 3);
  a(0, 0) = 1.1;
  a(1, 0) = 0.35;
  a(2, 0) = 0.06;
  a(3, 0) = 0.0008;
  a(0, 1) = -0.004;
  a(1, 1) = 0.0007;
  a(0, 2) = 1e-6;
  const PolynomialSensorModel model(a);
  ASSERT_TRUE(model.monotone_in_voltage());
  for (const double t_c : {20.0, 60.0, 98.0}) {
    for (double d = 1.5; d <= 10.0; d += 0.25) {
      const VoltageSolution solution = model.voltage_for(d, t_c);
      ASSERT_EQ(solution.clip, RailClip::kNone);
      ASSERT_NEAR(model.clearance_mm(solution.volts, t_c), d, 1e-9);
    }
  }
}

TEST(PolynomialSensorModel, NonMonotoneModelTakesTheFirstRootAboveTheBottomRail) {
  // d = 1 + 2 V - 0.3 V^2 rises to 4.33 mm at 3.33 V and falls after: two roots for d = 2 mm.
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(3, 1);
  a(0, 0) = 1.0;
  a(1, 0) = 2.0;
  a(2, 0) = -0.3;
  const PolynomialSensorModel model(a);
  EXPECT_FALSE(model.monotone_in_voltage());
  const VoltageSolution solution = model.voltage_for(2.0, 25.0);
  EXPECT_EQ(solution.clip, RailClip::kNone);
  EXPECT_NEAR(solution.volts, (2.0 - std::sqrt(4.0 - 1.2)) / 0.6, 1e-10);
  // Above the peak there is no root: the nearer rail is the one with the larger clearance.
  EXPECT_EQ(model.voltage_for(5.0, 25.0).clip, RailClip::kLow);
}

TEST(PolynomialSensorModel, RejectsModelsItCannotInvert) {
  EXPECT_THROW(PolynomialSensorModel(Eigen::MatrixXd::Constant(1, 2, 1.0)), BadArgument);
  Eigen::MatrixXd no_voltage_term = Eigen::MatrixXd::Zero(2, 2);
  no_voltage_term(0, 0) = 1.0;
  EXPECT_THROW(PolynomialSensorModel{no_voltage_term}, BadArgument);
  Eigen::MatrixXd with_nan = Eigen::MatrixXd::Ones(2, 2);
  with_nan(1, 1) = std::nan("");
  EXPECT_THROW(PolynomialSensorModel{with_nan}, BadArgument);
  EXPECT_THROW(PolynomialSensorModel(Eigen::MatrixXd::Ones(2, 2), 5.0, 5.0), BadArgument);
  EXPECT_THROW(PolynomialSensorModel(Eigen::MatrixXd::Ones(17, 1)), BadArgument);
}

TEST(PolynomialSensorModel, NewtonFromANearbyVoltageAgreesWithBrentAndItsRails) {
  const PolynomialSensorModel model = PolynomialSensorModel::thesis_eq_3_14();
  // Clearances past both rails, guesses from a tenth of a volt to the whole range away.
  for (const double t_c : {-20.0, 20.0, 61.0, 98.0, 120.0}) {
    for (double d = 0.5; d <= 12.0; d += 0.0625) {
      const VoltageSolution brent = model.voltage_for(d, t_c);
      for (const double guess : {0.0, 0.1, 3.3, 9.9, 10.0, brent.volts + 0.1, -1.0}) {
        const VoltageSolution newton = model.voltage_near(d, t_c, guess);
        ASSERT_EQ(newton.clip, brent.clip) << "d " << d << " T " << t_c << " guess " << guess;
        ASSERT_NEAR(newton.volts, brent.volts, 2e-12) << "d " << d << " T " << t_c;
      }
    }
  }
}

}  // namespace
}  // namespace flange::sim
