// SPDX-License-Identifier: MIT
// Each effect leaves its own mark: the signature a diagnosis would look for in a recording.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "aliasing.h"
#include "effect_catalogue.h"
#include "sensor_twin.h"
#include "spectrum.h"

namespace flange::sim {
namespace {

using testing::peak_frequency;
using testing::power_share_in_band;
using testing::tone_amplitude;

std::unique_ptr<Effect> effect(const std::string& name, const ParamValues& values = {}) {
  return make_effect(make_effect_settings(name, values, "test"), 0.0, 10.0, 42);
}

ChainSample sample_at(double t_s, double voltage_v = 5.0, double temp_c = 20.0) {
  ChainSample sample;
  sample.t_s = t_s;
  sample.clearance_mm = 5.0;
  sample.ambient_c = sample.coil_c = sample.thermocouple_c = temp_c;
  sample.voltage_v = voltage_v;
  return sample;
}

// The voltage an effect leaves on a constant 5 V input, sampled at fs for `seconds`.
std::vector<double> voltage_trace(Effect& e, double fs_hz, double seconds) {
  std::vector<double> trace;
  for (int n = 0; n < static_cast<int>(fs_hz * seconds); ++n) {
    ChainSample sample = sample_at(n / fs_hz);
    e.apply(sample);
    trace.push_back(sample.voltage_v);
  }
  return trace;
}

TEST(AliasFrequency, FoldsAboutMultiplesOfTheSampleRate) {
  EXPECT_DOUBLE_EQ(alias_frequency_hz(50.0, 6.0), 2.0);
  EXPECT_DOUBLE_EQ(alias_frequency_hz(100.0, 6.0), 2.0);
  EXPECT_DOUBLE_EQ(alias_frequency_hz(150.0, 6.0), 0.0);
  EXPECT_DOUBLE_EQ(alias_frequency_hz(51.0, 100.0), 49.0);
  EXPECT_DOUBLE_EQ(alias_frequency_hz(102.0, 100.0), 2.0);
  EXPECT_NEAR(alias_frequency_hz(6.387, 6.0), 0.387, 1e-12);
  EXPECT_DOUBLE_EQ(alias_frequency_hz(1.0, 6.0), 1.0);
}

TEST(MainsPickup, FiftyHertzAt6HzShowsAt2Hz) {
  auto mains = effect("mains_pickup", {{"harmonics", 1}, {"amplitude_v", 0.05}});
  const std::vector<double> trace = voltage_trace(*mains, 6.0, 60.0);
  EXPECT_NEAR(peak_frequency(trace, 6.0, 0.05, 3.0, 0.01), 2.0, 0.011);
  EXPECT_NEAR(tone_amplitude(trace, 6.0, 2.0), 0.05, 1e-3);
}

TEST(MainsPickup, HarmonicsAt100HzLandWhereAliasingPutsThem) {
  // 51 Hz (a grid off nominal) so that no tone sits on Nyquist: 51 -> 49, 102 -> 2, 153 -> 47.
  auto mains =
      effect("mains_pickup",
             {{"mains_hz", 51.0}, {"harmonics", 3}, {"amplitude_v", 0.1}, {"harmonic_ratio", 0.5}});
  const std::vector<double> trace = voltage_trace(*mains, 100.0, 10.0);
  const std::vector<double> expected_hz = {49.0, 2.0, 47.0};
  double amplitude_v = 0.1;
  for (int k = 1; k <= 3; ++k) {
    EXPECT_DOUBLE_EQ(alias_frequency_hz(51.0 * k, 100.0), expected_hz[k - 1]);
    EXPECT_NEAR(tone_amplitude(trace, 100.0, expected_hz[k - 1]), amplitude_v, 1e-3) << k;
    amplitude_v *= 0.5;
  }
  EXPECT_NEAR(peak_frequency(trace, 100.0, 0.1, 50.0, 0.1), 49.0, 0.051);
  EXPECT_LT(tone_amplitude(trace, 100.0, 25.0), 1e-3);
}

TEST(AdcQuantization, ValuesLieOnTheLsbGridWithinHalfAnLsb) {
  auto adc = effect("adc_quantization", {{"bits", 12}});
  const double lsb_v = 20.0 / 4096.0;
  for (double v = -9.99; v < 9.99; v += 0.0137) {
    ChainSample sample = sample_at(0.0, v);
    adc->apply(sample);
    const double code = (sample.voltage_v + 10.0) / lsb_v;
    ASSERT_NEAR(code, std::round(code), 1e-9) << v;
    ASSERT_LE(std::abs(sample.voltage_v - v), 0.5 * lsb_v + 1e-12) << v;
  }
  ChainSample over = sample_at(0.0, 12.0);
  adc->apply(over);
  EXPECT_DOUBLE_EQ(over.voltage_v, 10.0 - lsb_v);  // the top code
}

TEST(ThermalLag, PositiveTauCoilLagsARampByTau) {
  auto lag = effect("thermal_lag", {{"tau_s", 30.0}});
  const double rate_c_per_s = 0.05;
  for (int n = 0; n <= 1200 * 6; ++n) {
    const double t = n / 6.0;
    ChainSample sample = sample_at(t, 5.0, 20.0 + rate_c_per_s * t);
    lag->apply(sample);
    if (t > 900.0) {  // 30 time constants: the start-up transient is below 1e-12
      ASSERT_NEAR(sample.coil_c, 20.0 + rate_c_per_s * (t - 30.0), 1e-9);
      ASSERT_DOUBLE_EQ(sample.thermocouple_c, 20.0 + rate_c_per_s * t);
    }
  }
}

TEST(ThermalLag, NegativeTauThermocoupleLagsAndSineLosesGainAndPhase) {
  const double tau_s = 20.0;
  auto lag = effect("thermal_lag", {{"tau_s", -tau_s}});
  const double fs_hz = 6.0;
  const double f_hz = 0.01;  // omega tau = 1.26: gain 0.62, phase -51.5 degrees
  std::vector<double> input;
  std::vector<double> lagged;
  for (int n = 0; n < static_cast<int>(fs_hz * 1000.0); ++n) {
    const double t = n / fs_hz;
    ChainSample sample =
        sample_at(t, 5.0, 50.0 + 10.0 * std::sin(2.0 * std::numbers::pi * f_hz * t));
    lag->apply(sample);
    EXPECT_DOUBLE_EQ(sample.coil_c, sample.ambient_c);
    if (t >= 200.0) {  // after the transient, whole periods only (800 s = 8 periods)
      input.push_back(sample.ambient_c);
      lagged.push_back(sample.thermocouple_c);
    }
  }
  const double omega_tau = 2.0 * std::numbers::pi * f_hz * tau_s;
  EXPECT_NEAR(tone_amplitude(lagged, fs_hz, f_hz) / tone_amplitude(input, fs_hz, f_hz),
              1.0 / std::sqrt(1.0 + omega_tau * omega_tau), 2e-3);
  // Phase from the cross term: mean of lagged(t) * cos(input phase) against amplitude.
  double in_phase = 0.0;
  double quadrature = 0.0;
  for (std::size_t n = 0; n < lagged.size(); ++n) {
    const double t = 200.0 + static_cast<double>(n) / fs_hz;
    in_phase += (lagged[n] - 50.0) * std::sin(2.0 * std::numbers::pi * f_hz * t);
    quadrature += (lagged[n] - 50.0) * std::cos(2.0 * std::numbers::pi * f_hz * t);
  }
  EXPECT_NEAR(std::atan2(quadrature, in_phase), -std::atan(omega_tau), 2e-3);
}

TEST(ChannelSkew, PositiveSkewReportsTheTemperatureFromSkewEarlier) {
  auto skew = effect("channel_skew", {{"skew_s", 0.5}});
  for (int n = 0; n < 100; ++n) {
    const double t = n / 6.0;
    ChainSample sample = sample_at(t, 5.0, 20.0 + 2.0 * t);
    skew->apply(sample);
    const double expected_c = t < 0.5 ? 20.0 : 20.0 + 2.0 * (t - 0.5);
    ASSERT_NEAR(sample.thermocouple_c, expected_c, 1e-12) << t;
    ASSERT_DOUBLE_EQ(sample.voltage_v, 5.0);
  }
}

TEST(ChannelSkew, NegativeSkewDelaysTheVoltageInstead) {
  auto skew = effect("channel_skew", {{"skew_s", -0.25}});
  for (int n = 0; n < 300; ++n) {
    const double t = n / 100.0;
    ChainSample sample = sample_at(t, 1.0 + 3.0 * t, 40.0);
    skew->apply(sample);
    const double expected_v = t < 0.25 ? 1.0 : 1.0 + 3.0 * (t - 0.25);
    ASSERT_NEAR(sample.voltage_v, expected_v, 1e-12) << t;
    ASSERT_DOUBLE_EQ(sample.thermocouple_c, 40.0);
  }
}

// skew(t) = 1 - 2 h: the temperature late by 1 s at the start, the channels level after half an
// hour, the voltage late by 1 s after an hour.
TEST(ChannelSkew, ADriftingSkewMovesTheDelayFromOneChannelToTheOther) {
  auto skew = effect("channel_skew", {{"skew_s", 1.0}, {"drift_s_per_h", -2.0}});
  for (int n = 0; n < 3601; ++n) {
    const double t = n;
    ChainSample sample = sample_at(t, 1.0 + 0.001 * t, 20.0 + 0.01 * t);
    skew->apply(sample);
    const double skew_s = 1.0 - 2.0 * t / 3600.0;
    const double temperature_t = t - std::max(0.0, skew_s), voltage_t = t + std::min(0.0, skew_s);
    ASSERT_NEAR(sample.thermocouple_c, 20.0 + 0.01 * std::max(0.0, temperature_t), 1e-9) << t;
    ASSERT_NEAR(sample.voltage_v, 1.0 + 0.001 * std::max(0.0, voltage_t), 1e-9) << t;
  }
}

// A delay of a thousand samples held over twelve thousand: the points the delay line keeps are
// dropped from its front and its storage compacted many times, and every value is still the
// ramp's value skew_s back.
TEST(ChannelSkew, ALongDelayAtAHighRateReadsThePastThroughout) {
  auto skew = effect("channel_skew", {{"skew_s", 10.0}, {"drift_s_per_h", -20.0}});
  for (int n = 0; n < 12000; ++n) {
    const double t = n / 100.0;
    ChainSample sample = sample_at(t, 2.0, 20.0 + 0.5 * t);
    skew->apply(sample);
    const double skew_s = 10.0 - 20.0 * t / 3600.0;
    ASSERT_NEAR(sample.thermocouple_c, 20.0 + 0.5 * std::max(0.0, t - skew_s), 1e-9) << t;
    ASSERT_DOUBLE_EQ(sample.voltage_v, 2.0);
  }
}

TEST(AgeingDrift, OffsetGrowsAtTheGivenRatePerDay) {
  auto ageing = effect("ageing_drift", {{"rate_v_per_day", -0.08}, {"start_age_days", 10.0}});
  // Least-squares slope over two days sampled once a minute.
  double sum_t = 0.0, sum_v = 0.0, sum_tt = 0.0, sum_tv = 0.0;
  int count = 0;
  for (double t = 0.0; t <= 2.0 * 86400.0; t += 60.0) {
    ChainSample sample = sample_at(t);
    ageing->apply(sample);
    if (t == 0.0) {
      EXPECT_NEAR(sample.voltage_v, 5.0 - 0.8, 1e-12);  // ten days old at the start
    }
    sum_t += t;
    sum_v += sample.voltage_v;
    sum_tt += t * t;
    sum_tv += t * sample.voltage_v;
    ++count;
  }
  const double slope = (count * sum_tv - sum_t * sum_v) / (count * sum_tt - sum_t * sum_t);
  EXPECT_NEAR(slope * 86400.0, -0.08, 1e-9);
}

TEST(RangeCompression, BunchesLargeClearancesTogetherMoreWhenHot) {
  const PolynomialSensorModel nominal = PolynomialSensorModel::thesis_eq_3_14();
  auto compression = effect("range_compression");
  const auto output = [&](double d_mm, double t_c) {
    ChainSample sample = sample_at(0.0, nominal.voltage_for(d_mm, t_c).volts, t_c);
    compression->apply(sample);
    return sample.voltage_v;
  };
  // The voltage span of 8.5-10 mm, which the thesis saw collapse at 79-98 degC.
  const auto span_v = [&](double t_c) { return output(10.0, t_c) - output(8.5, t_c); };
  const auto nominal_span_v = [&](double t_c) {
    return nominal.voltage_for(10.0, t_c).volts - nominal.voltage_for(8.5, t_c).volts;
  };
  // No compression at room temperature, nor at 60 degC (the knee is still above 10 mm's 9.4 V).
  EXPECT_DOUBLE_EQ(span_v(20.0), nominal_span_v(20.0));
  EXPECT_DOUBLE_EQ(span_v(60.0), nominal_span_v(60.0));
  EXPECT_LT(span_v(80.0), 0.9 * nominal_span_v(80.0));
  EXPECT_LT(span_v(98.0) / nominal_span_v(98.0), 0.6 * span_v(80.0) / nominal_span_v(80.0));
  EXPECT_LT(span_v(98.0), 0.5);  // 1.5 mm squeezed into less than half a volt
  // Compression bends the characteristic over but never folds it back.
  for (double d = 8.0; d < 10.0; d += 0.05) ASSERT_LT(output(d, 98.0), output(d + 0.05, 98.0));
  // Small clearances are untouched even when hot.
  EXPECT_DOUBLE_EQ(output(4.0, 98.0), nominal.voltage_for(4.0, 98.0).volts);
}

TEST(Vibration, PowerLiesInItsBandWithTheGivenRms) {
  auto vibration = effect("vibration", {{"rms_mm", 0.1}, {"f_low_hz", 8.0}, {"f_high_hz", 12.0}});
  const double fs_hz = 100.0;
  std::vector<double> motion_mm;
  for (int n = 0; n < 6000; ++n) {
    ChainSample sample = sample_at(n / fs_hz);
    vibration->apply(sample);
    motion_mm.push_back(sample.clearance_mm - 5.0);
  }
  double power = 0.0;
  for (const double m : motion_mm) power += m * m;
  EXPECT_NEAR(std::sqrt(power / static_cast<double>(motion_mm.size())), 0.1, 0.01);
  EXPECT_GT(power_share_in_band(motion_mm, fs_hz, 7.9, 12.1), 0.97);
}

TEST(TempGainDrift, ScalesTheOutputByTheTemperatureRise) {
  auto drift = effect("temp_gain_drift", {{"gain_per_c", -1e-3}, {"reference_c", 20.0}});
  ChainSample cool = sample_at(0.0, 8.0, 20.0);
  drift->apply(cool);
  EXPECT_DOUBLE_EQ(cool.voltage_v, 8.0);
  ChainSample hot = sample_at(0.0, 8.0, 70.0);
  drift->apply(hot);
  EXPECT_NEAR(hot.voltage_v, 8.0 * (1.0 - 0.05), 1e-12);
  ChainSample hot_low = sample_at(0.0, 2.0, 70.0);
  drift->apply(hot_low);
  EXPECT_NEAR(hot_low.voltage_v, 2.0 * (1.0 - 0.05), 1e-12);  // a gain: larger at large V
}

TEST(TempOffsetDrift, ShiftsTheOutputByTheTemperatureRise) {
  auto drift = effect("temp_offset_drift", {{"offset_v_per_c", -2e-3}, {"reference_c", 25.0}});
  for (const double v : {1.0, 5.0, 9.0}) {
    ChainSample hot = sample_at(0.0, v, 95.0);
    drift->apply(hot);
    EXPECT_NEAR(hot.voltage_v - v, -0.14, 1e-12);
  }
}

TEST(Nonlinearity, BowsMidScaleAndVanishesAtTheEnds) {
  auto bow = effect("nonlinearity", {{"bow_v", 0.1}, {"s_curve_v", 0.0}});
  auto s_curve = effect("nonlinearity", {{"bow_v", 0.0}, {"s_curve_v", 0.1}});
  const auto shifted = [](Effect& e, double v) {
    ChainSample sample = sample_at(0.0, v);
    e.apply(sample);
    return sample.voltage_v - v;
  };
  EXPECT_NEAR(shifted(*bow, 5.0), 0.1, 1e-12);
  EXPECT_NEAR(shifted(*bow, 2.5), 0.075, 1e-12);
  EXPECT_NEAR(shifted(*bow, 1e-9), 0.0, 1e-9);
  EXPECT_NEAR(shifted(*s_curve, 5.0), 0.0, 1e-12);
  const double peak_v = 5.0 * (1.0 - 1.0 / std::sqrt(3.0));  // 21 % of scale
  EXPECT_NEAR(shifted(*s_curve, peak_v), -0.1, 1e-12);
  EXPECT_NEAR(shifted(*s_curve, 10.0 - peak_v), 0.1, 1e-12);
  EXPECT_NEAR(shifted(*s_curve, 10.0 - 1e-9), 0.0, 1e-8);
}

}  // namespace
}  // namespace flange::sim
