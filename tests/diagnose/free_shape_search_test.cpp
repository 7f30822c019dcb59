// SPDX-License-Identifier: MIT
// Each free-shape family's search (diagnose/data/candidates/free_shapes/) on a small synthetic
// bench session with a known answer, and the one search helper they share (grid_search.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "ageing_family.h"
#include "ageing_level_family.h"
#include "compression_surface_family.h"
#include "curve_family.h"
#include "family_makers.h"
#include "free_shape_fit.h"
#include "grid_search.h"
#include "lag_family.h"
#include "moving_knee_family.h"
#include "pivot_gain_family.h"
#include "ripple_family.h"
#include "skew_family.h"
#include "synthetic_bench.h"

namespace flange::diagnose::free_shapes {
namespace {

std::vector<double> plus(std::vector<double> a, const std::vector<double>& b) {
  for (std::size_t i = 0; i < a.size(); ++i) a[i] += b[i];
  return a;
}

// A linear family fitted with the same session as both parts.
FreeShapeFit fit_on_itself(LinearFamily& family, const SyntheticBench& bench,
                           const std::vector<double>& gap) {
  family.search(bench.part(), gap);
  return family.fit({bench.part(), bench.part(), gap, gap, false});
}

// ---- The search helper ---------------------------------------------------------------------

TEST(GridSearch, AnAxisIsSteppedByAccumulationUpToItsEnd) {
  EXPECT_EQ(stepped_axis(0.0, 1.0 + 1e-9, 0.25), (std::vector<double>{0.0, 0.25, 0.5, 0.75, 1.0}));
  EXPECT_EQ(stepped_axis(0.0, 0.99, 0.25), (std::vector<double>{0.0, 0.25, 0.5, 0.75}));
  EXPECT_EQ(lattice({{1.0, 2.0}, {3.0, 4.0}}),
            (std::vector<std::vector<double>>{{1.0, 3.0}, {1.0, 4.0}, {2.0, 3.0}, {2.0, 4.0}}));
}

TEST(GridSearch, OfEqualValuesTheFirstPointIsKept) {
  SearchPoint best{{9.0}};
  search_points(
      lattice({{-1.0, 1.0, 0.5}}),
      [](const std::vector<double>& at) { return std::abs(std::abs(at[0]) - 1.0); }, best);
  EXPECT_EQ(best.at, std::vector<double>{-1.0});
  EXPECT_EQ(best.value, 0.0);
}

TEST(GridSearch, APointWithoutAFiniteValueLeavesTheStart) {
  SearchPoint best{{7.0}};
  search_points(
      lattice({{1.0, 2.0}}),
      [](const std::vector<double>&) { return std::numeric_limits<double>::quiet_NaN(); }, best);
  EXPECT_EQ(best.at, std::vector<double>{7.0});
}

TEST(GridSearch, ThePatternDescendsFromTheLatticesBestToTheMinimum) {
  const Objective bowl = [](const std::vector<double>& at) {
    return std::pow(at[0] - 0.37, 2) + 4.0 * std::pow(at[1] + 1.23, 2);
  };
  const SearchPoint best =
      grid_search(lattice({stepped_axis(-3.0, 3.0, 1.0), stepped_axis(-3.0, 3.0, 1.0)}),
                  {0.5, 0.1, 0.02}, coordinate_moves(2), bowl, {{0.0, 0.0}});
  // To within half the finest step (and rounding).
  EXPECT_NEAR(best.at[0], 0.37, 0.0101);
  EXPECT_NEAR(best.at[1], -1.23, 0.0101);
  EXPECT_LT(best.value, 1e-3);
}

TEST(GridSearch, AMoveThatLeavesTheDomainIsNotTried) {
  // The minimum is at -1, but the domain stops at 0.
  const Objective bowl = [](const std::vector<double>& at) { return std::pow(at[0] + 1.0, 2); };
  const PatternMove down = [](const std::vector<double>& from, double step) {
    if (from[0] - step < 0.0) return std::optional<std::vector<double>>();
    return std::optional<std::vector<double>>(std::vector<double>{from[0] - step});
  };
  SearchPoint best{{2.0}, bowl({2.0})};
  refine_by_pattern({0.5, 0.1}, {down}, bowl, best);
  EXPECT_EQ(best.at, std::vector<double>{0.0});
}

// ---- The families' searches ----------------------------------------------------------------

// The voltage channel late by 2.3 s at the start, 1.7 s/h less later (a DAQ clock that drifts):
// off the lattice in both, so the pattern refinement must find it.
TEST(SkewSearch, FindsAKnownSkewAndItsDrift) {
  const SyntheticBench bench;
  const std::vector<double> gap =
      plus(SkewFamily::shift(bench.part(), {-2.3, 1.7, 0.0}), white_noise(bench.size(), 0.01, 1));
  SkewFamily skew;
  skew.search(bench.part(), gap);
  // Over half an hour the drift's rate and its curvature trade; the skew along the session does
  // not.
  EXPECT_NEAR(skew.law()[0], -2.3, 0.05);
  const FreeShapeFit fit = skew.fit({bench.part(), bench.part(), gap, gap, false});
  EXPECT_NEAR(fit.params.at("skew_s_at_start"), -2.3, 0.05);
  EXPECT_NEAR(fit.params.at("skew_s"), -2.3 + 1.7 * 0.25, 0.05);
  EXPECT_NEAR(fit.params.at("skew_s_at_end"), -2.3 + 1.7 * 0.5, 0.05);
  EXPECT_NEAR(fit.params.at("scale"), 1.0, 0.02);
}

// A ripple of 2.7 mm in the clearance (a lead screw's), 0.05 V, in noise of 0.02 V.
TEST(RippleSearch, FindsAKnownPeriod) {
  const SyntheticBench bench;
  std::vector<double> gap = white_noise(bench.size(), 0.02, 2);
  for (std::size_t i = 0; i < gap.size(); ++i) {
    gap[i] += 0.05 * std::sin(2.0 * std::numbers::pi * bench.series().clearance_mm[i] / 2.7 + 0.3);
  }
  RippleFamily ripple;
  ripple.search(bench.part(), gap);
  EXPECT_NEAR(ripple.period_mm(), 2.7, 0.01);
}

// A search that ends on an edge of its range reports a bound, not a value: a ripple longer than
// two periods across the calibration's range.
TEST(RippleSearch, ARippleLongerThanTheSearchIsABound) {
  const SyntheticBench bench;
  std::vector<double> gap = white_noise(bench.size(), 0.02, 6);
  for (std::size_t i = 0; i < gap.size(); ++i) {
    gap[i] += 0.1 * std::sin(2.0 * std::numbers::pi * bench.series().clearance_mm[i] / 60.0);
  }
  RippleFamily ripple;
  const FreeShapeFit fit = fit_on_itself(ripple, bench, gap);
  ASSERT_EQ(fit.search_edges.count("ripple_period_mm"), 1u) << ripple.period_mm();
  EXPECT_EQ(fit.search_edges.at("ripple_period_mm").substr(0, 3), ">= ");
  EXPECT_NEAR(std::stod(fit.search_edges.at("ripple_period_mm").substr(3)), ripple.period_mm(),
              0.01 * ripple.period_mm());
}

// A clearance range shorter than two of the shortest periods: nothing to search.
TEST(RippleSearch, NoPeriodOnARangeTooShortForTwo) {
  const SyntheticBench bench;
  RecordingSeries narrow = bench.series();
  for (double& d : narrow.clearance_mm) d = 5.0 + 0.1 * (d - 5.0);  // 0.85 mm of range
  const TwinReplay replay(narrow, SyntheticBench::nominal());
  RippleFamily ripple;
  ripple.search({narrow, replay}, white_noise(narrow.size(), 0.02, 3));
  EXPECT_EQ(ripple.period_mm(), 0.0);
}

// A clip above a knee at `knee_v(T)`: a third of the slope above it (no noise).
std::vector<double> clipped(const SyntheticBench& bench, double (*knee_v)(double temp_c)) {
  std::vector<double> gap(bench.size(), 0.0);
  for (std::size_t i = 0; i < gap.size(); ++i) {
    const double v = bench.replay().nominal_voltage()[i];
    const double knee = knee_v(bench.series().temp_c[i]);
    if (v > knee) gap[i] = -(2.0 / 3.0) * (v - knee);
  }
  return gap;
}
std::vector<double> compressed(const SyntheticBench& bench, double (*knee_v)(double temp_c)) {
  return plus(clipped(bench, knee_v), white_noise(bench.size(), 0.01, 4));
}

double falling_knee(double temp_c) { return 8.0 - 0.03 * std::max(0.0, temp_c - 40.0); }
double fixed_knee(double) { return 7.5; }

double rms_between(const std::vector<double>& a, const std::vector<double>& b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) sum += (a[i] - b[i]) * (a[i] - b[i]);
  return std::sqrt(sum / static_cast<double>(a.size()));
}

// The curve above the knee is free and 0 at the knee, so a knee lower by a knot of that curve,
// with the curve 0 up to the true knee, is the same shape: what the search must find is how far
// the knee falls from the coldest temperature to the hottest, and the shape.
TEST(MovingKneeSearch, FindsHowFarAKneeFallsAsTheCoilHeats) {
  const SyntheticBench bench;
  const std::vector<double> gap = compressed(bench, falling_knee);
  MovingKneeFamily knee(bench.part());
  knee.search(bench.part(), gap);
  EXPECT_TRUE(knee.knee_moves());
  EXPECT_FALSE(knee.shape_is_function_of_clearance_alone());
  const std::vector<double>& at = knee.temperature_knots_c();
  for (std::size_t k = 1; k < at.size(); ++k) {
    EXPECT_NEAR(knee.knee_v()[0] - knee.knee_v()[k], falling_knee(at[0]) - falling_knee(at[k]),
                0.05)
        << "at " << at[k] << " degC";
  }
  const FreeShapeFit fit = knee.fit({bench.part(), bench.part(), gap, gap, false});
  EXPECT_LT(rms_between(fit.cal_voltage_v, clipped(bench, falling_knee)), 0.005);
}

TEST(MovingKneeSearch, AKneeThatDoesNotMoveIsAFunctionOfClearanceAlone) {
  const SyntheticBench bench;
  const std::vector<double> gap = compressed(bench, fixed_knee);
  MovingKneeFamily knee(bench.part());
  knee.search(bench.part(), gap);
  EXPECT_FALSE(knee.knee_moves());
  EXPECT_TRUE(knee.shape_is_function_of_clearance_alone());
  for (double v : knee.knee_v()) EXPECT_LE(v, 7.5 + 0.05);
  const FreeShapeFit fit = knee.fit({bench.part(), bench.part(), gap, gap, false});
  EXPECT_LT(rms_between(fit.cal_voltage_v, clipped(bench, fixed_knee)), 0.005);
}

// The same two compressions through the class table's surface family: the one that does not
// change with temperature keeps the compression's name and names the class of a function of the
// clearance alone alike; the same surface raising the top (no compression does) is named that
// class, alike a compression.
TEST(CompressionSurfaceSearch, ASurfaceThatDoesNotChangeWithTemperatureIsAlikeANonlinearity) {
  const SyntheticBench bench;
  const auto surface =
      std::find_if(free_shape_families().begin(), free_shape_families().end(),
                   [](const FreeShapeFamily& f) { return f.make == make_compression_surface; });
  ASSERT_NE(surface, free_shape_families().end());
  for (const bool moving : {true, false}) {
    const std::vector<double> gap = compressed(bench, moving ? falling_knee : fixed_knee);
    const FreeShapeFit fit =
        fit_free_shape(*surface, {bench.part(), bench.part(), gap, gap, false});
    EXPECT_EQ(fit.family.effect, "range_compression") << fit.description;
    EXPECT_EQ(fit.also_of_class, moving ? "" : "nonlinearity") << fit.description;
  }
  std::vector<double> raised = compressed(bench, fixed_knee);
  for (double& v : raised) v = -v;
  const FreeShapeFit fit =
      fit_free_shape(*surface, {bench.part(), bench.part(), raised, raised, false});
  EXPECT_EQ(fit.family.effect, "nonlinearity") << fit.description;
  EXPECT_EQ(fit.also_of_class, "range_compression") << fit.description;
}

// An ageing that settles as 0.04 ln(1 + age / tau), tau one of the settlings searched (22 min),
// in noise of 5 mV; and a straight line of 2 V/day (without noise: over half an hour, a settling
// of ten days is a line to within a thousandth, which noise would choose between).
TEST(AgeingSearch, ChoosesAKnownSettling) {
  const SyntheticBench bench;
  const double tau_days = AgeingFamily::taus()[6];
  ASSERT_NEAR(tau_days, 0.0152, 1e-4);
  std::vector<double> settling = white_noise(bench.size(), 0.005, 5);
  std::vector<double> line(bench.size());
  for (std::size_t i = 0; i < settling.size(); ++i) {
    const double age_days = bench.series().t_s[i] / 86400.0;
    settling[i] += 0.04 * std::log1p(age_days / tau_days);
    line[i] = 0.01 + 2.0 * age_days;
  }
  AgeingFamily ageing;
  ageing.search(bench.part(), settling);
  EXPECT_EQ(ageing.settling_tau_days(), tau_days);
  AgeingFamily straight;
  straight.search(bench.part(), line);
  EXPECT_EQ(straight.settling_tau_days(), 0.0);
}

// A level that moved by 10 mV between a half-hour calibration session and a held-out session
// five days on (a rate of 2 mV/day: 0.04 mV over the calibration session, under its 5 mV noise):
// the held-out part chooses the rate. The same level at 1 V asks for a rate the calibration
// session rejects (its sum of squares would grow by far more than kSettlingLeeway sigma^2), so it
// is taken only as far as the calibration allows; with no step the held-out part takes none, nor
// after a pick, whose own carry-over the held-out level may be.
TEST(AgeingSearch, TheHeldOutLevelChoosesARateTheCalibrationLeavesOpen) {
  const SyntheticBench bench;
  const RecordedPart later{bench.series(), bench.replay(), 5.0 * 86400.0};
  const std::vector<double> noise = white_noise(bench.size(), 0.005, 7);
  const auto heldout_level = [&](double step_v, bool no_level_carried = true) {
    std::vector<double> heldout = white_noise(bench.size(), 0.005, 8);
    for (double& v : heldout) v += step_v;
    AgeingFamily ageing;
    ageing.search(bench.part(), noise);
    const FreeShapeFit fit =
        ageing.fit({bench.part(), later, noise, heldout, false, no_level_carried});
    double mean = 0.0;
    for (double v : fit.heldout_voltage_v) mean += v / static_cast<double>(bench.size());
    return std::pair{mean, fit.heldout_values};
  };
  const auto [moved, moved_values] = heldout_level(0.010);
  EXPECT_NEAR(moved, 0.010, 0.001);
  EXPECT_EQ(moved_values, 2);
  const auto [far, far_values] = heldout_level(1.0);
  EXPECT_GT(far, 0.01);
  EXPECT_LT(far, 0.2);
  EXPECT_EQ(far_values, 2);
  const auto [none, none_values] = heldout_level(0.0);
  EXPECT_NEAR(none, 0.0, 0.001);
  const auto [after_a_pick, after_a_pick_values] = heldout_level(0.010, false);
  EXPECT_NEAR(after_a_pick, 0.0, 0.001);
  EXPECT_EQ(after_a_pick_values, 1);
}

// An ageing that rose by 21 mV over a half-hour calibration session (1 V/day, in 5 mV of noise)
// and had settled 30 mV higher five days later, faster than any settling the calibration part
// allows: the continuing family carries the session's slope (or a settling it does not reject)
// past that level, the settled one stops at the session's end. The level between the sessions
// (AgeingLevelFamily) is chosen on the held-out part before any pick, and not after one.
TEST(AgeingSearch, ALevelBetweenTheSessionsThatNoSettlingReachesIsTaken) {
  const SyntheticBench bench;
  const RecordedPart later{bench.series(), bench.replay(), 5.0 * 86400.0};
  std::vector<double> calibration = white_noise(bench.size(), 0.005, 11);
  for (std::size_t i = 0; i < calibration.size(); ++i) {
    calibration[i] += 0.03 + 1.0 * bench.series().t_s[i] / 86400.0;
  }
  std::vector<double> heldout = white_noise(bench.size(), 0.005, 12);
  for (double& v : heldout) v += 0.081;
  const auto least_heldout_rms = [&](bool no_level_carried) {
    double least = 1e9;
    for (const FreeShapeFamily& family : free_shape_families()) {
      if (family.effect != "ageing_drift") continue;
      const FreeShapeFit fit = fit_free_shape(
          family, {bench.part(), later, calibration, heldout, false, no_level_carried});
      double sse = 0.0;
      for (std::size_t i = 0; i < heldout.size(); ++i) {
        sse += std::pow(heldout[i] - fit.heldout_voltage_v[i], 2);
      }
      least = std::min(least, std::sqrt(sse / static_cast<double>(heldout.size())));
    }
    return least;
  };
  EXPECT_LT(least_heldout_rms(true), 1.1 * 0.005);
  EXPECT_GT(least_heldout_rms(false), 2.0 * 0.005);
  // The level, which the calibration part does not move at all, is told by the held-out part:
  // a volt of it moves the fitted voltage there (over both parts, by about 1 / sqrt 2 V RMS).
  AgeingLevelFamily level;
  level.search(bench.part(), calibration);
  const FreeShapeFit fit = level.fit({bench.part(), later, calibration, heldout, false, true});
  EXPECT_NEAR(fit.params.at("level_between_sessions_v"), 0.081 - 0.03 - 1800.0 / 86400.0, 0.002);
  EXPECT_GT(fit.value_sensitivity_v.at("level_between_sessions_v"), 0.3);
}

// The coil's temperature a first-order lag of 240 s behind the recorded one (one of the family's
// own lags), and the reading 120 s behind the coil's (an advance of the recorded temperature).
TEST(LagSearch, TheMeanDelayHasTheKnownSignAndSize) {
  const SyntheticBench bench;
  const std::vector<double>& t = bench.series().t_s;
  const std::vector<double>& temp = bench.series().temp_c;
  const std::vector<double>& dv_dt = bench.replay().temperature_sensitivity_v_per_c();
  std::vector<double> sensor_lags = white_noise(bench.size(), 0.005, 6);
  std::vector<double> reading_lags = sensor_lags;
  double lagged = temp.front();
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (i > 0) lagged += (temp[i] - lagged) * (1.0 - std::exp(-(t[i] - t[i - 1]) / 240.0));
    sensor_lags[i] += dv_dt[i] * (lagged - temp[i]);
    reading_lags[i] += dv_dt[i] * (interpolate_at(t, temp, t[i] + 120.0) - temp[i]);
  }
  LagFamily sensor, reading;
  // Within a tenth: the mix's neighbouring lags share the fit.
  EXPECT_NEAR(fit_on_itself(sensor, bench, sensor_lags).params.at("tau_s"), 240.0, 24.0);
  EXPECT_NEAR(fit_on_itself(reading, bench, reading_lags).params.at("tau_s"), -120.0, 12.0);
}

// A voltage of -0.015 V per degC of the recorded temperature's lead over its own 240 s lag,
// several times what the coil's dV/dT would make of the same lag: the volts family finds the
// amplitude and the delay; the coil's family, whose scale is dV/dT, leaves more of it.
TEST(VoltsLagSearch, FindsTheAmplitudeAndDelayTheCoilsScaleCannotTake) {
  const SyntheticBench bench;
  const std::vector<double>& t = bench.series().t_s;
  const std::vector<double>& temp = bench.series().temp_c;
  std::vector<double> gap = white_noise(bench.size(), 0.005, 9);
  std::vector<double> effect(bench.size());
  double lagged = temp.front();
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (i > 0) lagged += (temp[i] - lagged) * (1.0 - std::exp(-(t[i] - t[i - 1]) / 240.0));
    effect[i] = -0.015 * (temp[i] - lagged);
  }
  gap = plus(gap, effect);
  VoltsLagFamily volts(bench.part());
  const FreeShapeFit found = fit_on_itself(volts, bench, gap);
  EXPECT_NEAR(found.params.at("v_per_c"), 0.015, 0.0015);  // the column is (S T - T)
  EXPECT_NEAR(found.params.at("delay_s"), 240.0, 24.0);
  EXPECT_EQ(found.params.count("tau_s"), 0u) << "no library lag member to hold";
  const auto left = [&](const FreeShapeFit& fit) {
    double sum = 0.0;
    for (std::size_t i = 0; i < gap.size(); ++i) sum += std::pow(gap[i] - fit.cal_voltage_v[i], 2);
    return std::sqrt(sum / static_cast<double>(gap.size()));
  };
  LagFamily coil;
  EXPECT_LT(left(found), 0.0055);  // the noise
  EXPECT_GT(left(fit_on_itself(coil, bench, gap)), left(found));
}

// A gain of 0.002 per degC about a pivot of 4 V.
TEST(PivotGainSearch, FindsAKnownPivot) {
  const SyntheticBench bench;
  std::vector<double> gap = white_noise(bench.size(), 0.005, 7);
  for (std::size_t i = 0; i < gap.size(); ++i) {
    gap[i] += (bench.replay().nominal_voltage()[i] - 4.0) * 0.002 * (bench.series().temp_c[i] - 20);
  }
  PivotGainFamily pivot(bench.part());
  EXPECT_NEAR(fit_on_itself(pivot, bench, gap).params.at("pivot_v"), 4.0, 0.1);
}

// A characteristic error that rises steeply towards the small clearances goes on past the
// calibration's lower end; a curve of the voltage (0 at its ends) has no reach to choose.
TEST(CurveSearch, ASmoothCurveOfClearanceGoesOnPastItsEnd) {
  const SyntheticBench bench;
  std::vector<double> gap = white_noise(bench.size(), 0.01, 8);
  for (std::size_t i = 0; i < gap.size(); ++i) {
    gap[i] += 0.2 * std::exp(-(bench.series().clearance_mm[i] - 1.5) / 0.8);
  }
  CurveFamily clearance(CurveOf::kClearance, bench.part());
  clearance.search(bench.part(), gap);
  const double spacing = knot_spacing(clearance.hats());
  EXPECT_NEAR(clearance.hats().reach_below * spacing, 1.0, 1e-9);  // kClearanceReachMm
  CurveFamily voltage(CurveOf::kVoltage, bench.part());
  voltage.search(bench.part(), gap);
  EXPECT_EQ(voltage.hats().reach_below, 0.0);
}

}  // namespace
}  // namespace flange::diagnose::free_shapes
