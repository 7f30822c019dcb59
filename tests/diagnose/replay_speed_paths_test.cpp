// SPDX-License-Identifier: MIT
// The shortcuts that keep a 100 Hz diagnosis fast must not change what it computes: the kept
// coil states give the replay the twin would give, the search rows of a long log and a search's
// lattice rows are increasing subsets whose fit still recovers the effect, and the mains fit's
// tone sum scores the point it finds exactly as a full replay does.
#include <gtest/gtest.h>

#include <cmath>

#include "effect_catalogue.h"
#include "effect_fit.h"
#include "sensor_twin.h"
#include "twin_recording.h"
#include "twin_replay.h"

namespace flange::diagnose {
namespace {

// A bench-like sweep at `fs_hz`: the micrometer's triangle over 1.5-10 mm (300 s period), the
// blower heating to about 95 degC and the cool-down.
RecordingSeries sweep(const std::vector<sim::EffectSettings>& effects, double fs_hz,
                      double duration_s, double noise_v, std::uint64_t seed) {
  sim::TwinConfig config;
  config.noise.voltage_std_v = noise_v;
  config.effects = effects;
  const auto triangle = [](double t) {
    const double u = std::fmod(t, 300.0) / 300.0;
    return 1.5 + 8.5 * (u < 0.5 ? 2.0 * u : 2.0 - 2.0 * u);
  };
  const auto blower = [duration_s](double t) {
    return t < 0.5 * duration_s ? 20.0 + 75.0 * (1.0 - std::exp(-t / 400.0))
                                : 20.0 + 75.0 * (1.0 - std::exp(-0.5 * duration_s / 400.0)) *
                                             std::exp(-(t - 0.5 * duration_s) / 500.0);
  };
  return record_twin(config, seed, fs_hz, duration_s, triangle, blower);
}

sim::EffectSettings effect(const std::string& name, const sim::ParamValues& values) {
  return sim::make_effect_settings(name, values, "test");
}

double rms_gap(const std::vector<double>& a, const std::vector<double>& b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) sum += (a[i] - b[i]) * (a[i] - b[i]);
  return std::sqrt(sum / static_cast<double>(a.size()));
}

TEST(ReplaySpeedPaths, KeptCoilStatesGiveWhatAFreshReplayGives) {
  const RecordingSeries series = sweep({}, 6.0, 1200.0, 0.0, 1);
  const sim::PolynomialSensorModel nominal = sim::PolynomialSensorModel::thesis_eq_3_14();
  const TwinReplay kept(series, nominal);
  const auto with_lag = [](double tau_s) {
    return std::vector<sim::EffectSettings>{effect("thermal_lag", {{"tau_s", tau_s}}),
                                            effect("range_compression", {})};
  };
  // Fill the cache past its size and come back to the first state: each answer must be the
  // one a replay that never saw the others gives, bit for bit.
  for (const double tau_s : {300.0, 600.0, 90.0, 1200.0, 45.0, 700.0, 800.0, 900.0, 300.0, 90.0}) {
    const TwinReplay fresh(series, nominal);
    ASSERT_EQ(kept.voltage(with_lag(tau_s)), fresh.voltage(with_lag(tau_s))) << tau_s;
  }
  // A late temperature channel changes what drives the coil, so it is part of the state.
  const std::vector<sim::EffectSettings> late_temperature = {
      effect("channel_skew", {{"skew_s", 5}})};
  const TwinReplay fresh(series, nominal);
  EXPECT_EQ(kept.voltage(late_temperature), fresh.voltage(late_temperature));
  EXPECT_NE(kept.voltage(late_temperature), kept.voltage({}));
}

// Mains pickup's tones, kept once the same settings come back (TwinReplay::time_terms), add
// what the effect itself adds: a replay holding them gives a fresh replay's voltages bit for
// bit, the first time (the tones evaluated), the second and later times (the kept terms), after
// other settings pushed them out, and after the rails' clamp with a sensor effect before it.
TEST(ReplaySpeedPaths, KeptMainsTonesGiveWhatAFreshReplayGives) {
  const RecordingSeries series = sweep({}, 100.0, 300.0, 0.0, 2);
  const sim::PolynomialSensorModel nominal = sim::PolynomialSensorModel::thesis_eq_3_14();
  const TwinReplay kept(series, nominal);
  const auto with_mains = [](double amplitude_v, double gain) {
    return std::vector<sim::EffectSettings>{
        effect("temp_gain_drift", {{"gain_per_c", gain}}),
        effect("mains_pickup", {{"amplitude_v", amplitude_v}, {"mains_hz", 60.0}})};
  };
  std::vector<std::pair<double, double>> asked;
  for (int k = 0; k < 20; ++k) asked.push_back({0.1 + 0.01 * k, 0.0});  // past what is kept
  for (const double gain : {1e-4, 2e-4, -1e-4, 3e-4}) asked.push_back({0.1, gain});
  for (int k = 0; k < 3; ++k) asked.push_back({0.12, 1e-4});
  for (const auto& [amplitude_v, gain] : asked) {
    const TwinReplay fresh(series, nominal);
    ASSERT_EQ(kept.voltage(with_mains(amplitude_v, gain)),
              fresh.voltage(with_mains(amplitude_v, gain)))
        << amplitude_v << " " << gain;
  }
  const TwinReplay fresh(series, nominal);
  EXPECT_NE(kept.voltage(with_mains(0.1, 0.0)), fresh.voltage(with_mains(0.11, 0.0)));
}

// The mains harmonics a replay keeps for the mains fit's tone sum are sin(k w t) and cos(k w t)
// bit for bit, made once per frequency: asked again, the same table.
TEST(ReplaySpeedPaths, KeptMainsHarmonicsAreTheSinesOfEverySample) {
  const RecordingSeries series = sweep({}, 100.0, 60.0, 0.0, 3);
  const TwinReplay replay(series, sim::PolynomialSensorModel::thesis_eq_3_14());
  const double w = 2.0 * 3.141592653589793 * 60.0;
  const auto table = replay.harmonics(w, 3);
  ASSERT_EQ(table->sin_kwt.size(), 3u);
  for (int k = 1; k <= 3; ++k) {
    for (std::size_t i = 0; i < series.size(); ++i) {
      ASSERT_EQ(table->sin_kwt[static_cast<std::size_t>(k - 1)][i], std::sin(k * w * series.t_s[i]));
      ASSERT_EQ(table->cos_kwt[static_cast<std::size_t>(k - 1)][i], std::cos(k * w * series.t_s[i]));
    }
  }
  EXPECT_EQ(replay.harmonics(w, 3), table);
  EXPECT_NE(replay.harmonics(2.0 * 3.141592653589793 * 50.0, 3), table);
}

// Stepping from the last rows finds the rows a binary search finds, forwards, backwards, on a
// row's own time, between repeated times and beyond either end: the same value, bit for bit.
TEST(ReplaySpeedPaths, TheSteppingInterpolatorAgreesWithTheBinarySearch) {
  const std::vector<double> t = {0.0, 0.1, 0.25, 0.25, 0.4, 0.55, 0.7, 0.7, 0.7, 1.0, 1.3};
  std::vector<double> values;
  for (std::size_t i = 0; i < t.size(); ++i) values.push_back(std::sin(3.0 * static_cast<double>(i)));
  SeriesInterpolator stepping(t, values);
  const std::vector<double> asked = {-1.0, 0.05, 0.25, 0.3, 0.7,  0.71, 1.29, 1.3, 2.0,
                                     0.26, 0.1,  0.0,  0.69, 1.0, 0.24, 0.7,  0.4, 0.56};
  for (const double at : asked) {
    ASSERT_EQ(stepping.at(at), interpolate_at(t, values, at)) << at;
  }
}

TEST(ReplaySpeedPaths, ALongLogIsSearchedOnAnIncreasingSubsetOfItsRows) {
  const sim::PolynomialSensorModel nominal = sim::PolynomialSensorModel::thesis_eq_3_14();
  const RecordingSeries short_log = sweep({}, 6.0, 6600.0, 0.0, 2);
  const TwinReplay short_replay(short_log, nominal);
  EXPECT_EQ(&short_replay.search_replay(), &short_replay);  // 39,601 rows: every row

  const RecordingSeries long_log = sweep({}, 100.0, 1800.0, 0.0, 3);  // 180,001 rows
  const TwinReplay replay(long_log, nominal);
  const TwinReplay& search = replay.search_replay();
  ASSERT_NE(&search, &replay);
  EXPECT_LE(search.size(), TwinReplay::kSearchRows);
  EXPECT_GT(search.size(), TwinReplay::kSearchRows * 3 / 4);
  const std::vector<double> picked_t = replay.at_search_rows(long_log.t_s);
  ASSERT_EQ(picked_t, search.times());
  for (std::size_t i = 1; i < picked_t.size(); ++i) ASSERT_GT(picked_t[i], picked_t[i - 1]);
  // Not a fixed stride: every fifth row of a 60 Hz tone at 100 Hz is one value (60 x 5 / 100 is
  // whole), the search rows see the tone.
  std::vector<double> tone(long_log.size());
  for (std::size_t i = 0; i < tone.size(); ++i) {
    tone[i] = std::sin(2 * M_PI * 60 * long_log.t_s[i] + 0.3);
  }
  const std::vector<double> picked_tone = replay.at_search_rows(tone);
  double spread = 0.0;
  for (const double v : picked_tone) spread = std::max(spread, std::abs(v - picked_tone[0]));
  EXPECT_GT(spread, 0.5);
}

TEST(ReplaySpeedPaths, TheSearchLatticeRunsOnAQuarterOfItsRows) {
  const sim::PolynomialSensorModel nominal = sim::PolynomialSensorModel::thesis_eq_3_14();
  const RecordingSeries tiny = sweep({}, 6.0, 1500.0, 0.0, 5);  // 9,001 rows: every row
  const TwinReplay tiny_replay(tiny, nominal);
  EXPECT_EQ(&tiny_replay.lattice_replay(), &tiny_replay);

  const RecordingSeries log = sweep({}, 6.0, 6600.0, 0.0, 2);  // 39,601 rows
  const TwinReplay replay(log, nominal);
  const TwinReplay& lattice = replay.search_replay().lattice_replay();
  ASSERT_NE(&lattice, &replay);
  EXPECT_LE(lattice.size(), TwinReplay::kLatticeRows);
  EXPECT_GT(lattice.size(), TwinReplay::kLatticeRows * 3 / 4);
  const std::vector<double> picked_t = replay.at_lattice_rows(log.t_s);
  ASSERT_EQ(picked_t, lattice.times());
  for (std::size_t i = 1; i < picked_t.size(); ++i) ASSERT_GT(picked_t[i], picked_t[i - 1]);
  EXPECT_GT(picked_t.back(), log.t_s.back() - 2.0);  // spread over the whole session

  // A 100 Hz log's lattice rows are a subset of its search rows.
  const RecordingSeries long_log = sweep({}, 100.0, 1800.0, 0.0, 3);
  const TwinReplay long_replay(long_log, nominal);
  const TwinReplay& search = long_replay.search_replay();
  EXPECT_EQ(&long_replay.lattice_replay(), &long_replay);  // a full replay has none of its own
  EXPECT_EQ(search.at_lattice_rows(long_replay.at_search_rows(long_log.t_s)),
            search.lattice_replay().times());

  // The fit found from a lattice on those rows: a lag recovered, scored on every row.
  const std::vector<sim::EffectSettings> truth = {effect("thermal_lag", {{"tau_s", 450}})};
  const RecordingSeries lagged = sweep(truth, 6.0, 6600.0, 0.05, 6);
  const TwinReplay lagged_replay(lagged, nominal);
  const EffectFit fit = fit_effect("thermal_lag", lagged_replay, lagged.voltage_v, {});
  EXPECT_NEAR(fit.settings.params.at("tau_s"), 450.0, 9.0);
  EXPECT_DOUBLE_EQ(fit.rms_v, rms_gap(lagged.voltage_v, lagged_replay.voltage({fit.settings})));
}

TEST(ReplaySpeedPaths, A100HzLagIsFittedOnTheSearchRowsAndScoredOnEveryRow) {
  const std::vector<sim::EffectSettings> truth = {effect("thermal_lag", {{"tau_s", 300}})};
  const RecordingSeries log = sweep(truth, 100.0, 1800.0, 0.05, 4);
  const TwinReplay replay(log, sim::PolynomialSensorModel::thesis_eq_3_14());
  const EffectFit fit = fit_effect("thermal_lag", replay, log.voltage_v, {});
  EXPECT_NEAR(fit.settings.params.at("tau_s"), 300.0, 6.0);
  EXPECT_DOUBLE_EQ(fit.rms_v, rms_gap(log.voltage_v, replay.voltage({fit.settings})));
  EXPECT_NEAR(fit.rms_v, 0.05, 0.002);
}

TEST(ReplaySpeedPaths, TheMainsToneSumScoresItsFitAsAFullReplayDoes) {
  const std::vector<sim::EffectSettings> truth = {
      effect("thermal_lag", {{"tau_s", 200}}),
      effect("mains_pickup", {{"amplitude_v", 0.2}, {"phase_deg", 40}, {"harmonic_ratio", 0.4}})};
  const RecordingSeries log = sweep(truth, 7.0, 2400.0, 0.03, 5);
  const TwinReplay replay(log, sim::PolynomialSensorModel::thesis_eq_3_14());
  const std::vector<sim::EffectSettings> modelled = {truth[0]};
  const EffectFit fit = fit_effect("mains_pickup", replay, log.voltage_v, modelled);
  std::vector<sim::EffectSettings> with = modelled;
  with.push_back(fit.settings);
  EXPECT_NEAR(fit.rms_v, rms_gap(log.voltage_v, replay.voltage(with)), 1e-12);
  EXPECT_NEAR(fit.rms_v, 0.03, 0.002);
  EXPECT_NEAR(fit.settings.params.at("amplitude_v"), 0.2, 0.01);
  EXPECT_NEAR(fit.settings.params.at("harmonic_ratio"), 0.4, 0.05);
}

}  // namespace
}  // namespace flange::diagnose
