// SPDX-License-Identifier: MIT
// The selection's rules (criteria.h) on small synthetic inputs with known answers: significance
// and its bootstrap bound, the tie, the preference for the library's formula, the first pick's
// chance gain, confounding, the backward step, the pass comparison, the most picks and the
// inclusion, which counts the class.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <optional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "backward.h"
#include "block_resamples.h"
#include "candidate.h"
#include "criteria.h"
#include "diagnosis_detail.h"
#include "effect_catalogue.h"
#include "effect_classes.h"
#include "forward.h"
#include "inclusion.h"
#include "library_candidates.h"
#include "parts.h"
#include "series_statistics.h"
#include "scoring.h"
#include "series_arithmetic.h"
#include "selection.h"
#include "sensor_twin.h"
#include "two_passes.h"

namespace flange::diagnose {
namespace {

// The twin's white noise in every test, V, and its variance: every gain below is a share of it.
constexpr double kSigma = 0.01;
constexpr double kVar = kSigma * kSigma;
constexpr int kRounds = 200;  // bootstrap resamples

std::vector<double> constant(std::size_t n, double v) { return std::vector<double>(n, v); }

// A held-out gap whose mean square is `share` of sigma^2 (a constant series: every resample's
// mean square is the same, so a choice's bootstrap bound equals its gain).
std::vector<double> leaving(std::size_t n, double share) {
  return constant(n, std::sqrt(share * kVar));
}

std::vector<double> white_noise(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0.0, kSigma);
  std::vector<double> e(n);
  for (double& v : e) v = noise(rng);
  return e;
}

std::vector<double> plus(std::vector<double> a, const std::vector<double>& b) {
  for (std::size_t i = 0; i < a.size(); ++i) a[i] += b[i];
  return a;
}

Candidate library_candidate(const std::string& name, std::vector<double> heldout_error) {
  Candidate c;
  c.fit.settings.name = name;
  c.heldout_error = std::move(heldout_error);
  return c;
}

Candidate free_candidate(const std::string& name, int free_values,
                         std::vector<double> heldout_error) {
  Candidate c = library_candidate(name, std::move(heldout_error));
  FreeShapeFit shape;
  shape.family = {name, "test"};
  shape.free_values = free_values;
  c.free_shape = shape;
  return c;
}

TEST(SelectionRules, ASignificantCandidateIsTaken) {
  // 1000 held-out samples of noise with a 3 sigma bias. Removing the bias gains
  // 9 sigma^2 + 6 sigma mean(noise) = 9 +- 0.2 sigma^2 (the noise's mean is sigma / sqrt(1000));
  // removing half of it gains 9 - 2.25 = 6.75 sigma^2; leaving it gains 0.
  const std::size_t n = 1000;
  const std::vector<double> noise = white_noise(n, 7);
  const std::vector<double> gap = plus(noise, constant(n, 3.0 * kSigma));
  const std::vector<Candidate> candidates = {
      library_candidate("thermal_lag", gap),
      library_candidate("nonlinearity", plus(noise, constant(n, 1.5 * kSigma))),
      library_candidate("temp_offset_drift", noise)};
  const BlockResamples resamples(n, kRounds, 1);
  const RoundScore round{gap, resamples, kSigma};
  const Choice choice = best_candidate(candidates, round, false);
  EXPECT_EQ(choice.best, 2u);
  EXPECT_NEAR(choice.gain / kVar, 9.0, 0.5);
  // Every resample holds the whole bias: the bound is near the gain, far above 0.
  EXPECT_GT(choice.lower / kVar, 8.0);
  EXPECT_TRUE(significant(choice, criteria::kLeastGainOfAPick * kVar));
  // The floor is what it is checked against: one above the gain is not met.
  EXPECT_FALSE(significant(choice, 20.0 * kVar));
}

TEST(SelectionRules, WhenTheBestGainIsNotConfirmedTheBestConfirmedOneIsChosen) {
  // 1000 held-out samples of noise; the picks leave a 1 sigma bias everywhere and 6 sigma more on
  // the 40 samples [480, 520). One candidate takes the 6 sigma there and leaves 1.05 sigma
  // elsewhere: a gain of (40 * (49 - 1) - 960 * 0.1025) / 1000 = 1.8 sigma^2, but a resample of 20
  // blocks of 50 misses the stretch with probability 0.14
  // (AGainThatResamplesDoNotConfirmIsNotSignificant) and then scores its loss elsewhere only, so
  // its 5 % bound is below 0: not significant. Another takes the 1 sigma everywhere: a gain of (960 * 1 + 40 * (49 - 36))
  // / 1000 = 1.5 sigma^2, about 1 sigma^2 on every resample. Before the rule the round chose the first
  // and stopped with nothing; it chooses the second.
  const std::size_t n = 1000;
  const std::vector<double> noise = white_noise(n, 13);
  std::vector<double> now = plus(noise, constant(n, kSigma));
  std::vector<double> stretch_taken = plus(noise, constant(n, 1.05 * kSigma)), bias_taken = noise;
  for (std::size_t i = 480; i < 520; ++i) {
    now[i] += 6.0 * kSigma;
    stretch_taken[i] = noise[i] + kSigma;
    bias_taken[i] += 6.0 * kSigma;
  }
  const std::vector<Candidate> candidates = {library_candidate("nonlinearity", stretch_taken),
                                             library_candidate("temp_offset_drift", bias_taken)};
  const BlockResamples resamples(n, kRounds, 1);
  const RoundScore round{now, resamples, kSigma};
  const double least = criteria::kLeastGainOfAPick * kVar;
  const Choice best = best_candidate(candidates, round, false);
  EXPECT_EQ(best.best, 0u);
  EXPECT_FALSE(significant(best, least));
  const Choice chosen = significant_choice(candidates, round, false, least);
  EXPECT_EQ(chosen.best, 1u);
  EXPECT_TRUE(significant(chosen, least));
  EXPECT_LT(chosen.gain, best.gain);
  // With no confirmed candidate the round's best stands (and is not significant).
  const std::vector<Candidate> alone = {candidates[0]};
  EXPECT_EQ(significant_choice(alone, round, false, least).best, 0u);
}

TEST(SelectionRules, ASmallGainIsNotSignificant) {
  // Constant gaps: the picks leave 2 sigma^2; one candidate 1.99 sigma^2 (a gain of 1 % of
  // sigma^2), another 1.97 (3 %). On every resample the gain is the same, so each bound is its
  // gain, > 0: only the floor kLeastGainOfAPick = 2 % decides.
  const std::size_t n = 640;
  const std::vector<double> now = leaving(n, 2.0);
  const std::vector<Candidate> candidates = {library_candidate("nonlinearity", leaving(n, 1.99)),
                                             library_candidate("nonlinearity", leaving(n, 1.97))};
  const BlockResamples resamples(n, kRounds, 1);
  const RoundScore round{now, resamples, kSigma};
  const Choice small = choice_of(candidates, 0, round);
  const Choice enough = choice_of(candidates, 1, round);
  EXPECT_NEAR(small.gain / kVar, 0.01, 1e-9);
  EXPECT_GT(small.lower, 0.0);
  EXPECT_FALSE(significant(small, criteria::kLeastGainOfAPick * kVar));
  EXPECT_NEAR(enough.gain / kVar, 0.03, 1e-9);
  EXPECT_GT(enough.lower, 0.0);
  EXPECT_TRUE(significant(enough, criteria::kLeastGainOfAPick * kVar));
}

TEST(SelectionRules, AGainThatResamplesDoNotConfirmIsNotSignificant) {
  // 1000 held-out samples of noise; the picks leave a 2 sigma bias on the 40 samples [480, 520).
  // The candidate removes it there and adds 0.2 sigma everywhere else. Its mean gain:
  // (40 * 4 - 960 * 0.04) / 1000 = 0.16 - 0.038 = 0.12 sigma^2 (+- about 0.03 from the noise's
  // cross terms), well above the 2 % floor. Resamples are blocks of max(32, 1000 / 20) = 50
  // samples starting uniformly in [0, 950]: a block meets the stretch when it starts in
  // (430, 520), 90 of 951 starts, so a resample of 20 blocks misses it with probability
  // (1 - 90 / 951)^20 = 0.14 > kGainLowerQuantile = 5 %; such a resample scores the candidate's
  // -0.04 sigma^2 elsewhere only, so the 5 % quantile of the gain is < 0.
  const std::size_t n = 1000;
  const std::vector<double> noise = white_noise(n, 11);
  std::vector<double> now = noise, after = noise;
  for (std::size_t i = 0; i < n; ++i) {
    if (i >= 480 && i < 520) {
      now[i] += 2.0 * kSigma;
    } else {
      after[i] += 0.2 * kSigma;
    }
  }
  // The same mean gain spread over the whole part: a bias b = sqrt(0.12) sigma taken everywhere.
  const std::vector<double> spread_now = plus(noise, constant(n, std::sqrt(0.12) * kSigma));
  const BlockResamples resamples(n, kRounds, 1);
  const RoundScore round{now, resamples, kSigma};
  const Choice choice = choice_of({library_candidate("nonlinearity", after)}, 0, round);
  EXPECT_GT(choice.gain, criteria::kLeastGainOfAPick * kVar);
  EXPECT_NEAR(choice.gain / kVar, 0.12, 0.05);
  EXPECT_LE(choice.lower, 0.0);
  EXPECT_FALSE(significant(choice, criteria::kLeastGainOfAPick * kVar));
  // Spread evenly, a gain of that size is confirmed by every resample: it is the concentration,
  // not the size, that fails the bound. (Its bound: 0.12 less 1.6 times the spread of
  // 2 b mean(noise) over ~1000 samples, 2 * 0.35 / 31.6 = 0.022: about 0.08 sigma^2.)
  const RoundScore spread{spread_now, resamples, kSigma};
  const Choice even = choice_of({library_candidate("nonlinearity", noise)}, 0, spread);
  EXPECT_NEAR(even.gain / kVar, 0.12, 0.05);
  EXPECT_GT(even.lower, 0.0);
  EXPECT_TRUE(significant(even, criteria::kLeastGainOfAPick * kVar));
}

TEST(SelectionRules, ATieGoesToFewerValues) {
  // The picks leave 2 sigma^2. Two free shapes: A with 8 values leaves 1.90 (gains 0.10 sigma^2),
  // B with 3 values leaves 1.91 (0.09: 0.01 below A, within kTieMargin = 0.02) or 1.93 (0.07:
  // 0.03 below, outside it).
  const std::size_t n = 640;
  const std::vector<double> now = leaving(n, 2.0);
  const BlockResamples resamples(n, kRounds, 1);
  const RoundScore round{now, resamples, kSigma};
  const std::vector<Candidate> tied = {free_candidate("nonlinearity", 8, leaving(n, 1.90)),
                                       free_candidate("temp_offset_drift", 3, leaving(n, 1.91))};
  EXPECT_EQ(best_candidate(tied, round, true).best, 1u);   // free shapes compete: fewer values
  EXPECT_EQ(best_candidate(tied, round, false).best, 0u);  // else the larger gain
  EXPECT_NEAR(best_candidate(tied, round, true).gain / kVar, 0.09, 1e-9);
  const std::vector<Candidate> apart = {free_candidate("nonlinearity", 8, leaving(n, 1.90)),
                                        free_candidate("temp_offset_drift", 3, leaving(n, 1.93))};
  EXPECT_EQ(best_candidate(apart, round, true).best, 0u);
  EXPECT_EQ(best_candidate(apart, round, false).best, 0u);
  // Fewer values listed first and outside the margin: the larger gain still wins.
  const std::vector<Candidate> first = {free_candidate("temp_offset_drift", 3, leaving(n, 1.93)),
                                        free_candidate("nonlinearity", 8, leaving(n, 1.90))};
  EXPECT_EQ(best_candidate(first, round, true).best, 1u);
}

TEST(SelectionRules, TheLibraryFormulaIsPreferredWhenAFreeShapeGainsNoMore) {
  // The picks leave 2 sigma^2; the free nonlinearity curve (index 1) leaves 1.90, gaining 0.10
  // sigma^2. The library's nonlinearity formula (index 0) leaves 1.91 (0.09: 0.01 less, within
  // kFreeShapeMustGainOverFormula = 0.02) -> the formula is taken; or 1.93 (0.07: 0.03 less) ->
  // the free shape stays. A library formula of another class (temp_offset_drift, 1.905) is never
  // taken in its place.
  const std::size_t n = 640;
  const std::vector<double> now = leaving(n, 2.0);
  const BlockResamples resamples(n, kRounds, 1);
  const RoundScore round{now, resamples, kSigma};
  for (const double formula_leaves : {1.91, 1.93}) {
    const std::vector<Candidate> candidates = {
        library_candidate("nonlinearity", leaving(n, formula_leaves)),
        free_candidate("nonlinearity", 8, leaving(n, 1.90)),
        library_candidate("temp_offset_drift", leaving(n, 1.905))};
    const Choice free = choice_of(candidates, 1, round);
    const Choice preferred = prefer_library_formula(candidates, free, round);
    const bool within = formula_leaves < 1.92;
    EXPECT_EQ(preferred.best, within ? 0u : 1u) << formula_leaves;
    EXPECT_NEAR(preferred.gain / kVar, within ? 0.09 : 0.10, 1e-9) << formula_leaves;
  }
  // A library choice is left as it is.
  const std::vector<Candidate> library = {library_candidate("nonlinearity", leaving(n, 1.95)),
                                          free_candidate("nonlinearity", 8, leaving(n, 1.90))};
  EXPECT_EQ(prefer_library_formula(library, choice_of(library, 0, round), round).best, 0u);
}

// The held-out gap of the first-pick tests: a slow sine of amplitude `amplitude` sigma and period
// 640 samples over 6400 samples (10 periods), no noise.
std::vector<double> slow_sine_gap(double amplitude, double phase_samples) {
  std::vector<double> gap(6400);
  for (std::size_t i = 0; i < gap.size(); ++i) {
    gap[i] = amplitude * kSigma *
             std::sin(2.0 * std::numbers::pi * (static_cast<double>(i) + phase_samples) / 640.0);
  }
  return gap;
}

TEST(SelectionRules, TheFirstPickNeedsWhatChanceGivesWithinItsBounds) {
  const BlockResamples none;
  // A gap shorter than 10 * kChanceShifts = 640 samples is not shifted: the upper bound.
  const std::vector<double> short_gap = leaving(600, 1.5);
  const std::vector<Candidate> exact = {library_candidate("nonlinearity", constant(600, 0.0))};
  EXPECT_NEAR(first_pick_least_gain(exact, {short_gap, none, kSigma}) / kVar,
              criteria::kMostLeastGainOfAFirstPick, 1e-12);
  // A candidate that predicts nothing (its held-out gap is the gap) gains 0 at every lag: the
  // lower bound.
  const std::vector<double> flat = slow_sine_gap(0.1, 0.0);
  EXPECT_NEAR(
      first_pick_least_gain({library_candidate("thermal_lag", flat)}, {flat, none, kSigma}) / kVar,
      criteria::kLeastLeastGainOfAFirstPick, 1e-12);
  // The lags are n / 10 + k (8 n / 10) / 63 = 640 + (5120 k) / 63 (integer division) for
  // n = 6400; k = 5 gives 640 + 406 = 1046. A candidate predicting p(i) = A sin(w (i + 1046)),
  // w = 2 pi / 640, meets the gap shifted by that lag: its chance gain there is
  // (2 sum gap(i + 1046) p(i) - sum p^2) / n = A^2 - A^2 / 2 = A^2 / 2, and at a lag L
  // A^2 (cos(w (L - 1046)) - 1 / 2), so none gives more. At lag 0 it does not line up:
  // cos(2 pi 1046 / 640) = -0.67, its real gain is A^2 (-0.67 - 0.5) < 0.
  // A^2 = 0.007 sigma^2 gives 0.0035 sigma^2, within [0.002, 0.005]; A^2 = 0.02 gives 0.01,
  // clamped to 0.005; A^2 = 0.002 gives 0.001, clamped to 0.002.
  for (const auto& [a2, expected] :
       std::vector<std::pair<double, double>>{{0.007, 0.0035}, {0.02, 0.005}, {0.002, 0.002}}) {
    const double a = std::sqrt(a2);
    const std::vector<double> gap = slow_sine_gap(a, 0.0);
    std::vector<double> error = gap;
    const std::vector<double> prediction = slow_sine_gap(a, 1046.0);
    for (std::size_t i = 0; i < gap.size(); ++i) error[i] -= prediction[i];
    // Beside it, a candidate that predicts nothing (its held-out gap is the gap).
    const std::vector<Candidate> candidates = {library_candidate("thermal_lag", gap),
                                               library_candidate("nonlinearity", error)};
    const RoundScore round{gap, none, kSigma};
    EXPECT_LT(gain_of(candidates[1], round), 0.0) << a2;
    EXPECT_NEAR(first_pick_least_gain(candidates, round) / kVar, expected, 1e-9) << a2;
  }
}

// The lags summed side by side (kShiftsAtOnce at a time) give each lag's sum in row order, the
// bits of one running sum per lag, for any number of lags and any lag up to n - 1.
TEST(SelectionRules, ShiftedDotsAreEachLagsSumInRowOrder) {
  const std::size_t n = 1001;
  std::vector<double> gap(n), predicted(n);
  for (std::size_t i = 0; i < n; ++i) {
    gap[i] = std::sin(0.37 * static_cast<double>(i)) * (1.0 + 1e-3 * static_cast<double>(i));
    predicted[i] = std::cos(0.11 * static_cast<double>(i * i % 97)) / 3.0;
  }
  std::vector<std::size_t> lags = {0, 1, 100, 999, 1000, 500, 7, 64, 333, 101, 250};
  const std::vector<double> dots = shifted_dots(gap, predicted, lags);
  ASSERT_EQ(dots.size(), lags.size());
  for (std::size_t k = 0; k < lags.size(); ++k) {
    double dot = 0.0;
    for (std::size_t i = 0; i < n; ++i) dot += gap[(i + lags[k]) % n] * predicted[i];
    EXPECT_EQ(dots[k], dot) << lags[k];
  }
}

TEST(SelectionRules, AnotherClassWithinTheMarginIsConfounded) {
  // The picks leave 2 sigma^2; the choice, a free nonlinearity curve, leaves 1.90 (gains 0.10).
  // Within kConfoundingMargin = 0.02 of it: the library nonlinearity (0.095, the same class: not
  // named), temp_offset_drift twice (0.09 and 0.085: named once) and temp_gain_drift (0.081).
  // Beyond it: ageing_drift (0.079) and thermal_lag (0.07).
  const std::size_t n = 640;
  const std::vector<double> now = leaving(n, 2.0);
  const BlockResamples resamples(n, kRounds, 1);
  const RoundScore round{now, resamples, kSigma};
  const std::vector<Candidate> candidates = {
      free_candidate("nonlinearity", 8, leaving(n, 1.90)),
      library_candidate("nonlinearity", leaving(n, 1.905)),
      library_candidate("temp_offset_drift", leaving(n, 1.91)),
      library_candidate("ageing_drift", leaving(n, 1.921)),
      free_candidate("temp_offset_drift", 4, leaving(n, 1.915)),
      library_candidate("thermal_lag", leaving(n, 1.93)),
      library_candidate("temp_gain_drift", leaving(n, 1.919))};
  const Choice choice = choice_of(candidates, 0, round);
  EXPECT_EQ(confounded_classes(candidates, choice, round),
            (std::vector<std::string>{"temp_offset_drift", "temp_gain_drift"}));
  // Alone with its own class's formula, nothing is confounded.
  const std::vector<Candidate> own = {candidates[0], candidates[1]};
  EXPECT_TRUE(confounded_classes(own, choice_of(own, 0, round), round).empty());
}

// A part of a bench session: `n` samples at 10 Hz, the clearance stepping over 1.5 to 3.5 mm every
// 20 samples, the temperature rising from 20 to 30 degC; the voltage is set by the test.
RecordingSeries bench_part(std::size_t n, double t0_s) {
  RecordingSeries s;
  for (std::size_t i = 0; i < n; ++i) {
    s.t_s.push_back(t0_s + 0.1 * static_cast<double>(i));
    s.clearance_mm.push_back(1.5 + 0.25 * static_cast<double>((i / 20) % 9));
    s.temp_c.push_back(20.0 + 10.0 * static_cast<double>(i) / static_cast<double>(n));
    s.voltage_v.push_back(0.0);
  }
  return s;
}

// A calibration part and a held-out part of `n` samples each (bench_part), replayed on the
// nominal twin of sim::TwinConfig{}; their voltages are set by the test.
struct BenchPair {
  explicit BenchPair(std::size_t n)
      : cal(bench_part(n, 0.0)),
        ho(bench_part(n, 30.0)),
        parts{cal,
              ho,
              TwinReplay(cal, sim::TwinConfig{}.nominal),
              TwinReplay(ho, sim::TwinConfig{}.nominal),
              false,
              std::nullopt} {}
  BenchPair(const BenchPair&) = delete;
  BenchPair& operator=(const BenchPair&) = delete;
  RecordingSeries cal, ho;
  Parts parts;
};

// `periods` periods of a sine of `amplitude` sigma over `n` samples, at `phase` radians.
std::vector<double> curve(std::size_t n, double amplitude, double periods, double phase) {
  std::vector<double> v(n);
  for (std::size_t i = 0; i < n; ++i) {
    v[i] = amplitude * kSigma *
           std::sin(2.0 * std::numbers::pi * periods * static_cast<double>(i) /
                        static_cast<double>(n) +
                    phase);
  }
  return v;
}

// A free-shape pick of class `name` adding `cal` and `heldout` to the twin's voltage.
Pick free_pick(const std::string& name, std::vector<double> cal, std::vector<double> heldout) {
  Candidate c = free_candidate(name, 6, {});
  c.free_shape->cal_voltage_v = std::move(cal);
  c.free_shape->heldout_voltage_v = std::move(heldout);
  Pick pick;
  pick.finding.name = name;
  pick.step.candidates = {std::move(c)};
  pick.modelled_index = -1;
  return pick;
}

// Two free-shape picks, a nonlinearity curve A then an offset curve B, on a held-out part of 300
// samples whose voltage is the nominal twin's plus A, plus B when `both`, plus noise; whether
// drop_unneeded_picks keeps them.
Selection after_backward_steps(bool both) {
  const std::size_t n = 300;
  BenchPair bench(n);
  RecordingSeries &cal = bench.cal, &ho = bench.ho;
  const Parts& parts = bench.parts;
  const std::vector<double> a_cal = curve(n, 5.0, 2.0, 0.0), a_ho = curve(n, 5.0, 2.0, 1.0);
  const std::vector<double> b_cal = curve(n, 5.0, 0.5, 0.0), b_ho = curve(n, 5.0, 0.5, 0.5);
  cal.voltage_v = plus(plus(parts.cal_replay.voltage({}), plus(a_cal, b_cal)), white_noise(n, 3));
  ho.voltage_v = plus(plus(parts.ho_replay.voltage({}), a_ho), white_noise(n, 4));
  if (both) ho.voltage_v = plus(ho.voltage_v, b_ho);
  Selection selection;
  selection.noise_v = kSigma;
  selection.cal_free_v = plus(a_cal, b_cal);
  selection.ho_free_v = plus(a_ho, b_ho);
  selection.picks.push_back(free_pick("nonlinearity", a_cal, a_ho));
  selection.picks.push_back(free_pick("temp_offset_drift", b_cal, b_ho));
  selection.confounded = {"nonlinearity and ageing_drift explain ...",
                          "temp_offset_drift and ageing_drift explain ..."};
  drop_unneeded_picks(parts, selection);
  return selection;
}

TEST(SelectionRules, ABackwardStepDropsAnUnneededPick) {
  // The held-out voltage holds A only: the final model (A + B added) leaves noise - B. Without B
  // it leaves the noise: the mean square changes by -ms(B) = -12.5 sigma^2 (a 5 sigma sine),
  // below kRemovalMargin = 0.02 sigma^2: B is dropped. Without A it would rise by about
  // +12.5 sigma^2: A stays (and, alone, is not weighed again).
  const Selection only_a = after_backward_steps(false);
  ASSERT_EQ(only_a.picks.size(), 1u);
  EXPECT_EQ(only_a.picks[0].finding.name, "nonlinearity");
  ASSERT_EQ(only_a.dropped.size(), 1u);
  EXPECT_TRUE(only_a.dropped[0].starts_with("temp_offset_drift was selected")) << only_a.dropped[0];
  // Its confounding sentence goes with it; its free curve leaves the free voltages.
  EXPECT_EQ(only_a.confounded,
            std::vector<std::string>{"nonlinearity and ageing_drift explain ..."});
  const std::vector<double> a_ho = curve(300, 5.0, 2.0, 1.0);
  for (std::size_t i = 0; i < a_ho.size(); ++i) EXPECT_NEAR(only_a.ho_free_v[i], a_ho[i], 1e-12);
  // What is left is the noise: RMS sigma within a few % (300 samples).
  EXPECT_NEAR(rms_of(only_a.current_error) / kSigma, 1.0, 0.15);
  // Both curves in the held-out voltage: taking out either raises the mean square by about
  // 12.5 sigma^2; neither is dropped.
  const Selection both = after_backward_steps(true);
  EXPECT_EQ(both.picks.size(), 2u);
  EXPECT_TRUE(both.dropped.empty());
  EXPECT_EQ(both.confounded.size(), 2u);
}

// A pass's outcome as free_pass_wins reads it: what it leaves (mean square in sigma^2) and how
// many picks.
Selection pass_leaving(double share, std::size_t picks) {
  Selection s;
  s.noise_v = kSigma;
  s.current_error = leaving(640, share);
  s.picks.resize(picks);
  return s;
}

TEST(SelectionRules, TheFreePassMustLeaveLessByTheMargin) {
  // The library pass leaves 1.5 sigma^2 (RMS 1.22 sigma, above kExplainedRatio 1.1) with two
  // picks. kPassComparisonMargin = 0.02 sigma^2.
  const Selection library = pass_leaving(1.5, 2);
  // Leaves less by 0.03: wins, with as many picks, whether or not the library named several.
  EXPECT_TRUE(free_pass_wins(library, pass_leaving(1.47, 2), true));
  EXPECT_TRUE(free_pass_wins(library, pass_leaving(1.47, 2), false));
  // Less by 0.01 only: loses.
  EXPECT_FALSE(free_pass_wins(library, pass_leaving(1.49, 2), true));
  // One class leaving 0.01 more (within the margin): wins only where the library named several.
  EXPECT_TRUE(free_pass_wins(library, pass_leaving(1.51, 1), true));
  EXPECT_FALSE(free_pass_wins(library, pass_leaving(1.51, 1), false));
  // One class leaving 0.03 more: loses.
  EXPECT_FALSE(free_pass_wins(library, pass_leaving(1.53, 1), true));
  // ... unless both leave the noise: the library 1.0 sigma^2, the free pass 1.2 (RMS 1.095 sigma,
  // within 1.1): 0.2 more, but fewer classes, where the library named several.
  EXPECT_TRUE(free_pass_wins(pass_leaving(1.0, 2), pass_leaving(1.2, 1), true));
  EXPECT_FALSE(free_pass_wins(pass_leaving(1.0, 2), pass_leaving(1.2, 1), false));
  // No picks at all is not fewer classes.
  EXPECT_FALSE(free_pass_wins(library, pass_leaving(1.49, 0), true));
}

// The held-out offsets of the four effects in AtMostThreePicks, in sigma.
const std::vector<std::pair<std::string, double>>& four_offsets() {
  static const std::vector<std::pair<std::string, double>> offsets = {{"nonlinearity", 8.0},
                                                                      {"temp_offset_drift", 6.0},
                                                                      {"temp_gain_drift", 4.0},
                                                                      {"thermal_lag", 3.0}};
  return offsets;
}

double offset_of(const std::string& name) {
  for (const auto& [effect, offset] : four_offsets()) {
    if (effect == name) return offset * kSigma;
  }
  return 0.0;
}

// Every round's library candidates, kept in `rounds` as the other pass would have
// left them, so that select_bias_effects weighs them without fitting: round r's candidates are
// every bias class not yet taken, each with its catalogue defaults; the four of four_offsets()
// take their offset off what the picks leave, the others take nothing. Round r takes the r-th.
void keep_rounds(const Parts& parts, LibraryRounds& rounds, const std::vector<double>& ho_gap) {
  std::vector<std::string> names = bias_classes_in_catalogue_order();
  std::vector<sim::EffectSettings> modelled;
  std::vector<double> left = ho_gap;
  for (const auto& [taken, offset] : four_offsets()) {
    std::vector<Candidate> candidates;
    for (const std::string& name : names) {
      Candidate c = library_candidate(name, left);
      for (double& v : c.heldout_error) v -= offset_of(name);
      c.fit.settings = sim::make_effect_settings(name, {}, "selection_rules_test");
      c.with = modelled;
      c.with.push_back(c.fit.settings);
      candidates.push_back(std::move(c));
    }
    rounds.keep(
        {names, modelled, 0, parts.calibration.voltage_v, parts.heldout.voltage_v, kSigma},
        candidates);
    modelled.push_back(sim::make_effect_settings(taken, {}, "selection_rules_test"));
    for (double& v : left) v -= offset * kSigma;
    std::erase(names, taken);
  }
}

// A level between the sessions may be chosen on the held-out part while no pick can carry one:
// none, or a skew (the voltage's rate of change times a delay) and the mains (lines fitted on
// each session); not after a temperature law, which continued to the held-out temperatures may
// leave a level of its own there.
TEST(SelectionRules, ALevelBetweenTheSessionsIsChosenOnlyWhileNoPickCarriesOne) {
  const auto with_picks = [](const std::vector<std::string>& names) {
    Selection selection;
    for (const std::string& name : names) {
      Pick pick;
      pick.finding.name = name;
      selection.picks.push_back(std::move(pick));
    }
    return selection;
  };
  EXPECT_TRUE(no_level_carried(with_picks({})));
  EXPECT_TRUE(no_level_carried(with_picks({"channel_skew", "mains_pickup"})));
  EXPECT_FALSE(no_level_carried(with_picks({"channel_skew", "temp_offset_drift"})));
  EXPECT_FALSE(no_level_carried(with_picks({"thermal_lag"})));
}

TEST(SelectionRules, AtMostThreePicks) {
  static_assert(criteria::kMostPicks == 3);
  // A held-out gap of noise plus four offsets, 8, 6, 4 and 3 sigma, each removed by one class.
  // Taking a from what is left, S, gains S^2 - (S - a)^2: from 21 sigma the 8 gains 272 sigma^2,
  // then 120 (the 6), 40 (the 4), and the 3 would gain 9: each far above 2 % of sigma^2.
  const std::size_t n = 300;
  BenchPair bench(n);
  RecordingSeries &cal = bench.cal, &ho = bench.ho;
  const Parts& parts = bench.parts;
  cal.voltage_v = plus(parts.cal_replay.voltage({}), white_noise(n, 5));
  ho.voltage_v = plus(parts.ho_replay.voltage({}), white_noise(n, 6));
  for (double& v : ho.voltage_v) v += 21.0 * kSigma;
  Selection selection;
  selection.noise_v = kSigma;
  selection.cal_free_v.assign(n, 0.0);
  selection.ho_free_v.assign(n, 0.0);
  selection.ho_gap = ho_target(parts, selection);
  const std::vector<double> nominal_ho = parts.ho_replay.voltage({});
  for (std::size_t i = 0; i < n; ++i) selection.ho_gap[i] -= nominal_ho[i];
  selection.raw_ho_gap = selection.ho_gap;
  LibraryRounds rounds;
  keep_rounds(parts, rounds, selection.ho_gap);
  DiagnoseOptions options;
  options.estimate_noise = false;
  select_bias_effects(parts, rounds, options, std::nullopt, selection);
  ASSERT_EQ(selection.picks.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(selection.picks[k].finding.name, four_offsets()[k].first);
  }
  // Left: the noise and the 3 sigma offset, RMS sqrt(9 + 1) sigma; the fourth round, kept, would
  // have taken it significantly: the rounds stopped at kMostPicks, not for want of a gain.
  EXPECT_NEAR(rms_of(selection.current_error) / kSigma, std::sqrt(10.0), 0.3);
  std::vector<std::string> untaken = bias_classes_in_catalogue_order();
  for (std::size_t k = 0; k < 3; ++k) std::erase(untaken, four_offsets()[k].first);
  const std::vector<Candidate> fourth =
      library_candidates(
      parts, rounds, {untaken, selection.modelled, 0, cal.voltage_v, ho.voltage_v, kSigma});
  const Choice next = best_candidate(fourth, round_score(selection), false);
  EXPECT_EQ(fourth[next.best].fit.settings.name, "thermal_lag");
  EXPECT_TRUE(significant(next, criteria::kLeastGainOfAPick * kVar));
}

TEST(SelectionRules, TheScreenRefitsTheBestOnEitherPartAndThoseAlikeToTheBest) {
  static_assert(criteria::kRefittedCandidatesOfARound == 3);
  static_assert(criteria::kRefitAlsoWithin == criteria::kConfoundingMargin);
  const auto in_var = [](std::vector<double> shares) {
    for (double& v : shares) v *= kVar;
    return shares;
  };
  // The calibration part ranking as the held-out part does adds nothing.
  const auto refit = [&](const std::vector<double>& heldout, double noise_v) {
    return candidates_to_refit(in_var(heldout), in_var(heldout), noise_v);
  };
  // The best three however far apart, and no other.
  EXPECT_EQ(refit({5.0, 1.0, 3.0, 9.0, 2.0}, kSigma), (std::vector<std::size_t>{1, 2, 4}));
  // Beyond the three, those within 2 % of sigma^2 of the best (10.019 is, 10.5 is not).
  EXPECT_EQ(refit({12.0, 10.01, 10.5, 13.0, 10.0, 11.0, 10.015, 10.019}, kSigma),
            (std::vector<std::size_t>{1, 4, 6, 7}));
  // Equals are taken in candidate order; every equal of the best is refitted; fewer than three
  // candidates are all refitted.
  EXPECT_EQ(refit({1.0, 3.0, 3.0, 3.0}, 0.0), (std::vector<std::size_t>{0, 1, 2}));
  EXPECT_EQ(refit({4.0, 4.0, 4.0, 4.0}, 0.0), (std::vector<std::size_t>{0, 1, 2, 3}));
  EXPECT_EQ(refit({7.0, 6.0}, kSigma), (std::vector<std::size_t>{0, 1}));
  // A candidate last on the held-out part but first on the calibration part is refitted, as are
  // the calibration part's next two; each candidate once.
  EXPECT_EQ(candidates_to_refit(in_var({2.0, 1.0, 3.0, 4.0, 9.0, 5.0}),
                                in_var({6.0, 5.0, 7.0, 2.0, 1.0, 8.0}), kSigma),
            (std::vector<std::size_t>{0, 1, 2, 3, 4}));
  EXPECT_EQ(candidates_to_refit(in_var({2.0, 1.0, 3.0, 4.0, 9.0, 5.0}),
                                in_var({2.0, 1.0, 3.0, 8.0, 9.0, 7.0}), kSigma),
            (std::vector<std::size_t>{0, 1, 2}));
}

TEST(SelectionRules, AScreenedRoundChoosesAsTheFullyRefittedRoundDoes) {
  // A pair with two effects on the twin, an offset drift with temperature and a gain drift, and
  // noise. The first round's pick soaks up part of the second effect; in the second round the
  // screen refits only its best candidates. Refitted, a candidate is the one the full round makes
  // (the same searches in the same order), and the best of the full round is among those the
  // screen refits: the round chooses the same candidate with the same fits and held-out gap.
  const std::size_t n = 300;
  BenchPair bench(n);
  const Parts& parts = bench.parts;
  const std::vector<sim::EffectSettings> truth = {
      sim::make_effect_settings("temp_offset_drift", {{"offset_v_per_c", 4e-3}}, "test"),
      sim::make_effect_settings("temp_gain_drift", {}, "test")};
  bench.cal.voltage_v = plus(parts.cal_replay.voltage(truth), white_noise(n, 11));
  bench.ho.voltage_v = plus(parts.ho_replay.voltage(truth), white_noise(n, 12));
  const std::vector<double>& cal_v = bench.cal.voltage_v;
  const std::vector<double>& ho_v = bench.ho.voltage_v;
  std::vector<std::string> names = bias_classes_in_catalogue_order();
  const BlockResamples resamples(n, kRounds, 3);

  LibraryRounds rounds;
  const std::vector<Candidate> first =
      library_candidates(parts, rounds, {names, {}, 0, cal_v, ho_v, kSigma});
  const std::vector<double> gap = minus(ho_v, parts.ho_replay.voltage({}));
  const Choice first_choice = best_candidate(first, {gap, resamples, kSigma}, false);
  const std::vector<sim::EffectSettings> modelled = {first[first_choice.best].fit.settings};
  std::erase(names, modelled[0].name);

  const std::vector<Candidate> screened =
      library_candidates(parts, rounds, {names, modelled, 0, cal_v, ho_v, kSigma});
  std::vector<Candidate> full;
  for (const std::string& name : names) {
    Candidate c;
    c.fit = fit_effect(name, parts.cal_replay, cal_v, modelled);
    c.with = modelled;
    c.with.push_back(c.fit.settings);
    backfit(c.with, 0, parts.cal_replay, cal_v);
    c.heldout_error = minus(ho_v, parts.ho_replay.voltage(c.with));
    full.push_back(std::move(c));
  }
  const std::vector<double> now = first[first_choice.best].heldout_error;
  const RoundScore score{now, resamples, kSigma};
  const Choice by_screen = best_candidate(screened, score, false);
  const Choice by_full = best_candidate(full, score, false);
  ASSERT_EQ(by_screen.best, by_full.best);
  EXPECT_EQ(screened[by_screen.best].heldout_error, full[by_full.best].heldout_error);
  ASSERT_EQ(screened[by_screen.best].with.size(), full[by_full.best].with.size());
  for (std::size_t k = 0; k < full[by_full.best].with.size(); ++k) {
    EXPECT_EQ(screened[by_screen.best].with[k].params, full[by_full.best].with[k].params);
  }
  EXPECT_EQ(by_screen.gain, by_full.gain);
  EXPECT_GT(by_screen.gain, criteria::kLeastGainOfAPick * kVar);  // a real second pick
  // Not every candidate was refitted: the screen saved searches.
  std::vector<double> screened_ms;
  for (const Candidate& c : screened) screened_ms.push_back(std::pow(rms_of(c.heldout_error), 2));
  std::vector<double> calibration_ms;
  for (const Candidate& c : screened) calibration_ms.push_back(c.fit.rms_v * c.fit.rms_v);
  EXPECT_LT(candidates_to_refit(screened_ms, calibration_ms, kSigma).size(), names.size());
}

// Inclusion counts the class, not the member: a round whose chosen candidate is its class's
// coarse curve (taken over a finer one that gains alike, the tie) names the class again on every
// resample where the finer curve of the same class wins; a resample won by another class does
// not.
TEST(SelectionRules, InclusionCountsAWinOfAnotherMemberOfTheChosenClass) {
  // Constant series: every resample's mean square is the series' own, so each candidate's
  // standing is the same on every resample.
  const std::size_t n = 1000;
  const BlockResamples resamples(n, kRounds, 3);
  Step step;
  step.noise_v = kSigma;
  step.candidates = {free_candidate("temp_offset_drift", 7, leaving(n, 0.25)),
                     free_candidate("temp_offset_drift", 19, leaving(n, 0.01)),
                     free_candidate("thermal_lag", 6, leaving(n, 0.64))};
  step.chosen = 0;
  EXPECT_DOUBLE_EQ(share_of_wins(step, leaving(n, 4.0), resamples), 1.0);
  // The same round with the finer curve of another class: the chosen one wins no resample.
  step.candidates[1].fit.settings.name = "nonlinearity";
  EXPECT_DOUBLE_EQ(share_of_wins(step, leaving(n, 4.0), resamples), 0.0);
}

}  // namespace
}  // namespace flange::diagnose
