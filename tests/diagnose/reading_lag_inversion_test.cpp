// SPDX-License-Identifier: MIT
// A late thermocouple (thermal_lag with tau_s < 0) is undone by leading the reading by tau times
// its slope. A bench thermocouple reads with noise of a tenth of a degree; the slope taken from
// neighbouring samples would carry that noise times tau / dt into the coil's temperature (some
// 200 degC behind a 400 s lag at 9 Hz), and no reading lag could be fitted on such a bench.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "effect_catalogue.h"
#include "effect_fit.h"
#include "sensor_twin.h"
#include "twin_recording.h"
#include "twin_replay.h"

namespace flange::diagnose {
namespace {

// An oven bench at 9 Hz: heating to about 90 degC over 600 s, a hold and a cool-down, under a
// 300 s micrometer triangle over 2-9 mm.
RecordingSeries oven_bench(const std::vector<sim::EffectSettings>& effects,
                           double temperature_noise_c, std::uint64_t seed) {
  sim::TwinConfig config;
  config.noise.voltage_std_v = 0.02;
  config.noise.temperature_std_c = temperature_noise_c;
  config.effects = effects;
  const auto triangle = [](double t) {
    const double u = std::fmod(t, 300.0) / 300.0;
    return 2.0 + 7.0 * (u < 0.5 ? 2.0 * u : 2.0 - 2.0 * u);
  };
  const auto oven = [](double t) {
    const double heated = 20.0 + 70.0 * (1.0 - std::exp(-std::min(t, 3000.0) / 600.0));
    return t < 3000.0 ? heated : 20.0 + (heated - 20.0) * std::exp(-(t - 3000.0) / 900.0);
  };
  return record_twin(config, seed, 9.0, 5400.0, triangle, oven);
}

sim::EffectSettings late_reading(double tau_s) {
  return sim::make_effect_settings("thermal_lag", {{"tau_s", -tau_s}}, "test");
}

TEST(ReadingLagInversion, TheCoilTemperatureBehindANoisyReadingKeepsTheReadingsNoise) {
  const RecordingSeries clean = oven_bench({late_reading(400.0)}, 0.0, 1);
  const RecordingSeries noisy = oven_bench({late_reading(400.0)}, 0.1, 1);
  const std::vector<double> from_clean = ambient_from_recorded(clean, {late_reading(400.0)});
  const std::vector<double> from_noisy = ambient_from_recorded(noisy, {late_reading(400.0)});
  double sum = 0.0;
  for (std::size_t i = 0; i < from_clean.size(); ++i) {
    sum += std::pow(from_noisy[i] - from_clean[i], 2);
  }
  // The reading's own 0.1 degC, and a little from the slope's window (local_slopes).
  EXPECT_LT(std::sqrt(sum / static_cast<double>(from_clean.size())), 0.15);
  // The clean reading led by its slope is the oven's own temperature, but for the bend where the
  // oven turns from heating to cooling, which a window of tau / 8 either side rounds off.
  const RecordingSeries unlagged = oven_bench({}, 0.0, 1);
  double worst = 0.0, square_sum = 0.0;
  for (std::size_t i = 0; i < from_clean.size(); ++i) {
    worst = std::max(worst, std::abs(from_clean[i] - unlagged.temp_c[i]));
    square_sum += std::pow(from_clean[i] - unlagged.temp_c[i], 2);
  }
  EXPECT_LT(std::sqrt(square_sum / static_cast<double>(from_clean.size())), 0.3);
  EXPECT_LT(worst, 3.0);
}

TEST(ReadingLagInversion, AReadingLagIsFittedBehindANoisyThermocouple) {
  const sim::PolynomialSensorModel nominal = sim::PolynomialSensorModel::thesis_eq_3_14();
  for (const double tau_s : {60.0, 400.0}) {
    const RecordingSeries bench = oven_bench({late_reading(tau_s)}, 0.1, 2);
    const TwinReplay replay(bench, nominal);
    const EffectFit fit = fit_effect("thermal_lag", replay, bench.voltage_v, {});
    EXPECT_NEAR(fit.settings.params.at("tau_s"), -tau_s, 0.1 * tau_s) << tau_s;
    EXPECT_LT(fit.rms_v, 0.022) << tau_s;  // the voltage noise, 0.02 V, and little more
  }
}

}  // namespace
}  // namespace flange::diagnose
