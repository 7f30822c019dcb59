// SPDX-License-Identifier: MIT
// The twin as a whole: nominal output, rail flags and counts, noise level and reproducibility,
// and effects running in chain order on their own random streams.
#include "sensor_twin.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "sim_error.h"

namespace flange::sim {
namespace {

TwinConfig noiseless() {
  TwinConfig config;
  config.noise.voltage_std_v = 0.0;
  return config;
}

EffectSettings defaults_of(const std::string& name) {
  return make_effect_settings(name, {}, "test");
}

TEST(SensorTwin, NoiselessTwinOutputsTheInvertedNominalModel) {
  SensorTwin twin(noiseless(), 1);
  const PolynomialSensorModel nominal = PolynomialSensorModel::thesis_eq_3_14();
  for (double d = 1.5; d <= 10.0; d += 0.5) {
    const Reading reading = twin.step({d, d, 64.0});
    EXPECT_EQ(reading.clip, RailClip::kNone);
    EXPECT_NEAR(nominal.clearance_mm(reading.voltage_v, 64.0), d, 1e-9);
    EXPECT_DOUBLE_EQ(reading.temp_c, 64.0);  // the thermocouple reads the sensor's temperature
  }
}

TEST(SensorTwin, FlagsAndCountsSamplesOutsideTheSensorRange) {
  SensorTwin twin(noiseless(), 1);
  const Reading close = twin.step({0.0, 0.4, 20.0});
  const Reading normal = twin.step({0.1, 5.0, 20.0});
  const Reading far1 = twin.step({0.2, 11.5, 20.0});
  const Reading far2 = twin.step({0.3, 15.0, 20.0});
  EXPECT_EQ(close.clip, RailClip::kLow);
  EXPECT_EQ(close.voltage_v, 0.0);
  EXPECT_EQ(normal.clip, RailClip::kNone);
  EXPECT_EQ(far1.clip, RailClip::kHigh);
  EXPECT_EQ(far2.voltage_v, 10.0);
  EXPECT_EQ(twin.clip_counts().low, 1);
  EXPECT_EQ(twin.clip_counts().high, 2);
}

TEST(SensorTwin, EffectPushingPastTheRailIsClippedAndFlagged) {
  TwinConfig config = noiseless();
  config.effects.push_back(make_effect_settings("temp_gain_drift", {{"gain_per_c", 0.01}}, "test"));
  SensorTwin twin(config, 1);
  const Reading reading = twin.step({0.0, 10.0, 98.0});  // 9.3 V nominal, gain 1.78
  EXPECT_EQ(reading.voltage_v, 10.0);
  EXPECT_EQ(reading.clip, RailClip::kHigh);
  EXPECT_EQ(twin.clip_counts().high, 1);
}

TEST(SensorTwin, DefaultNoiseIsTheRmsOfThesisTable41) {
  const std::vector<double> table_4_1_v = {0.05818,   0.0983705, 0.107465, 0.04565,
                                           0.064083,  0.0637246, 0.054814, 0.132915,
                                           0.0113445, 0.0134643, 0.050675, 0.02942};
  double sum_squares = 0.0;
  for (const double s : table_4_1_v) sum_squares += s * s;
  const double pooled_v = std::sqrt(sum_squares / static_cast<double>(table_4_1_v.size()));
  EXPECT_NEAR(TwinConfig{}.noise.voltage_std_v, pooled_v, 1e-5);

  SensorTwin twin(TwinConfig{}, 7);
  SensorTwin clean(noiseless(), 7);
  double sum = 0.0;
  double sum_sq = 0.0;
  constexpr int kSamples = 40000;
  for (int n = 0; n < kSamples; ++n) {
    const TrueState truth{n / 6.0, 5.0, 40.0};
    const double noise = twin.step(truth).voltage_v - clean.step(truth).voltage_v;
    sum += noise;
    sum_sq += noise * noise;
  }
  const double mean = sum / kSamples;
  EXPECT_NEAR(mean, 0.0, 4.0 * pooled_v / std::sqrt(kSamples));
  EXPECT_NEAR(std::sqrt(sum_sq / kSamples - mean * mean), pooled_v, 0.02 * pooled_v);
}

TEST(SensorTwin, SameSeedSameReadingsOtherSeedOtherReadings) {
  TwinConfig config;
  config.effects = {defaults_of("vibration"), defaults_of("mains_pickup")};
  SensorTwin first(config, 11);
  SensorTwin again(config, 11);
  SensorTwin other(config, 12);
  int differing = 0;
  for (int n = 0; n < 1000; ++n) {
    const TrueState truth{n / 100.0, 6.0, 50.0};
    const Reading a = first.step(truth);
    const Reading b = again.step(truth);
    ASSERT_EQ(a.voltage_v, b.voltage_v);
    ASSERT_EQ(a.temp_c, b.temp_c);
    if (other.step(truth).voltage_v != a.voltage_v) ++differing;
  }
  EXPECT_EQ(differing, 1000);
}

TEST(SensorTwin, SwitchingAnEffectOnLeavesTheNoiseStreamAlone) {
  // The difference between the twins is then exactly the mains tone.
  TwinConfig with_mains;
  with_mains.effects = {make_effect_settings("mains_pickup", {{"harmonics", 1}}, "test")};
  SensorTwin plain(TwinConfig{}, 5);
  SensorTwin mains(with_mains, 5);
  for (int n = 0; n < 600; ++n) {
    const double t = n / 6.0;
    const TrueState truth{t, 4.0, 30.0};
    const double pickup = mains.step(truth).voltage_v - plain.step(truth).voltage_v;
    ASSERT_NEAR(pickup, 0.02 * std::sin(2.0 * std::numbers::pi * 50.0 * t + std::numbers::pi / 6.0),
                1e-12);
  }
}

TEST(SensorTwin, EffectsRunInChainOrderWhateverTheListOrder) {
  // Quantisation must come after the offset drift, or its output would be off the LSB grid.
  TwinConfig forward = noiseless();
  forward.effects = {defaults_of("temp_offset_drift"), defaults_of("adc_quantization")};
  TwinConfig backward = noiseless();
  backward.effects = {defaults_of("adc_quantization"), defaults_of("temp_offset_drift")};
  SensorTwin a(forward, 3);
  SensorTwin b(backward, 3);
  const double lsb_v = 20.0 / 65536.0;
  for (double d = 2.0; d < 9.0; d += 0.37) {
    const Reading ra = a.step({d, d, 77.0});
    EXPECT_EQ(ra.voltage_v, b.step({d, d, 77.0}).voltage_v);
    const double code = (ra.voltage_v + 10.0) / lsb_v;
    EXPECT_NEAR(code, std::round(code), 1e-6);
  }
}

TEST(SensorTwin, ThermalLagMakesTheCoilAndThermocoupleDisagree) {
  TwinConfig config = noiseless();
  config.effects = {make_effect_settings("thermal_lag", {{"tau_s", 100.0}}, "test")};
  SensorTwin lagged(config, 1);
  SensorTwin direct(noiseless(), 1);
  // A step from 20 to 90 degC: the thermocouple jumps, the coil (and so the voltage) follows.
  lagged.step({0.0, 8.0, 20.0});
  const Reading now = lagged.step({1.0, 8.0, 90.0});
  EXPECT_DOUBLE_EQ(now.temp_c, 90.0);
  EXPECT_NE(now.voltage_v, direct.step({1.0, 8.0, 90.0}).voltage_v);
  const Reading later = lagged.step({2000.0, 8.0, 90.0});
  EXPECT_NEAR(later.voltage_v, direct.step({2000.0, 8.0, 90.0}).voltage_v, 1e-9);
}

// A housing that lags in the heat: V += A (sum_k w_k y_k - T), y_k the ambient through a lag of
// tau_k. The oven ramps at b from rest until t1, then holds: each lag trails by
// b tau (1 - exp(-t / tau)) on the ramp and closes on the held value as exp(-(t - t1) / tau)
// after it, so the recording is known in closed form at every sample.
TEST(SensorTwin, AVoltsLagAddsItsOwnVoltsPerDegreeOfAMixOfLagsBehindTheAmbient) {
  const double a = -0.035, b = 0.05, t1 = 600.0, fs_hz = 6.0;
  const std::array<double, 3> tau = {240.0, 60.0, 960.0}, w = {0.7, 0.5, -0.2};
  TwinConfig config = noiseless();
  config.effects = {make_effect_settings("thermal_lag_volts",
                                         {{"v_per_c", a},
                                          {"tau_1_s", tau[0]},
                                          {"weight_1", w[0]},
                                          {"tau_2_s", tau[1]},
                                          {"weight_2", w[1]},
                                          {"tau_3_s", tau[2]},
                                          {"weight_3", w[2]}},
                                         "test")};
  SensorTwin lagged(config, 1), direct(noiseless(), 1);
  double largest_v = 0.0;
  for (int n = 0; n <= static_cast<int>(1800 * fs_hz); ++n) {
    const double t = n / fs_hz;
    const double temp_c = 20.0 + b * std::min(t, t1);
    double mix = 0.0;
    for (std::size_t k = 0; k < tau.size(); ++k) {
      const double at_t1 = 20.0 + b * t1 - b * tau[k] * (1.0 - std::exp(-t1 / tau[k]));
      const double y = t <= t1 ? temp_c - b * tau[k] * (1.0 - std::exp(-t / tau[k]))
                               : temp_c - (temp_c - at_t1) * std::exp(-(t - t1) / tau[k]);
      mix += w[k] * y;
    }
    const Reading with = lagged.step({t, 5.0, temp_c});
    const Reading without = direct.step({t, 5.0, temp_c});
    ASSERT_NEAR(with.voltage_v - without.voltage_v, a * (mix - temp_c), 1e-9) << "t = " << t;
    EXPECT_EQ(with.temp_c, temp_c);  // the thermocouple reads the ambient
    largest_v = std::max(largest_v, std::abs(with.voltage_v - without.voltage_v));
  }
  EXPECT_GT(largest_v, 0.15);  // at t1 the mix trails the ambient by 4.8 degC: 0.17 V
}

TEST(SensorTwin, RejectsAnEffectTwiceAndBadNoise) {
  TwinConfig twice;
  twice.effects = {defaults_of("vibration"), defaults_of("vibration")};
  EXPECT_THROW(SensorTwin(twice, 1), BadArgument);
  TwinConfig negative;
  negative.noise.voltage_std_v = -0.1;
  EXPECT_THROW(SensorTwin(negative, 1), BadArgument);
  TwinConfig not_finite;
  not_finite.noise.temperature_std_c = std::nan("");
  EXPECT_THROW(SensorTwin(not_finite, 1), BadArgument);
}

}  // namespace
}  // namespace flange::sim
