// SPDX-License-Identifier: MIT
// What a locomotive's axles share, taken away at each axle's own scale
// (locomotive_common_mode.h): the route's curving multiplies every wheel's wear rate, so an axle
// wearing faster than the median carries more of the shared wander than the median; taken away
// at coefficient 1 the rest is a bend the drift search fits, fitted with the axle's own
// coefficient it is not, and a drifting sensor still stands out.
#include "locomotive_common_mode.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "sensor_drift.h"

namespace flange::host {
namespace {

constexpr int kDays = 120;
constexpr int kAxles = 6;

// Six axles over 120 days; each week the route's curving multiplies the left flanges' wear by
// one factor and the right flanges' by another (0.4-1.6, the same on every axle); axle a's
// wheels wear at (2 + 2a) 1e-5 (left) and (1 + 2a) 1e-5 (right) mm per km; the right sensor of
// `drifting_axle` (0-based; -1: none) drifts by 0.01 mm/day from day 40.
struct Locomotive {
  std::vector<AxleSeries> axles;
  std::vector<WearSeries> left, right;
};

Locomotive locomotive(int drifting_axle) {
  std::mt19937 draw(4747);
  std::uniform_real_distribution<double> day_km(150.0, 750.0), route(0.4, 1.6);
  std::normal_distribution<double> scatter(0.0, 0.003);
  Locomotive loco;
  loco.axles.resize(kAxles);
  loco.left.resize(kAxles);
  loco.right.resize(kAxles);
  std::vector<double> left_wear(kAxles, 3.0), right_wear(kAxles, 3.0);
  double km = 0.0, left_factor = 1.0, right_factor = 1.0;
  for (int day = 0; day < kDays; ++day) {
    if (day % 7 == 0) {
      left_factor = route(draw);
      right_factor = route(draw);
    }
    if (day % 7 == 3) continue;  // a depot day
    const double run_km = day_km(draw);
    km += run_km;
    for (int a = 0; a < kAxles; ++a) {
      left_wear[a] += run_km * (2 + 2 * a) * 1e-5 * left_factor;
      right_wear[a] += run_km * (1 + 2 * a) * 1e-5 * right_factor;
      const double drift = a == drifting_axle && day > 40 ? 0.01 * (day - 40) : 0.0;
      const double yl = left_wear[a] + scatter(draw), yr = right_wear[a] + drift + scatter(draw);
      AxleSeries& axle = loco.axles[a];
      axle.run_id.push_back(day);
      for (WearSeries* series : {&axle.sum, &axle.difference, &loco.left[a], &loco.right[a]}) {
        series->km.push_back(km);
        series->day.push_back(day);
        series->segment.push_back(0);
      }
      axle.sum.y.push_back(yl + yr);
      axle.difference.y.push_back(yr - yl);
      loco.left[a].y.push_back(yl);
      loco.right[a].y.push_back(yr);
    }
  }
  return loco;
}

// Axle a's candidates with the shared part taken away at coefficient 1, and with the shapes
// fitted at the axle's own scale as well.
DriftCandidates candidates(const Locomotive& loco, const CommonMode& common, int a,
                           bool own_scale) {
  const auto& run_id = loco.axles[a].run_id;
  std::map<std::int64_t, double> left_shared, right_shared;
  for (const auto& [run, sum] : common.sum_mm) {
    left_shared[run] = (sum - common.difference_mm.at(run)) / 2.0;
    right_shared[run] = (sum + common.difference_mm.at(run)) / 2.0;
  }
  WearSeries difference =
      without_common_mode(loco.axles[a].difference, run_id, common.difference_mm);
  WearSeries left = without_common_mode(loco.left[a], run_id, left_shared);
  WearSeries right = without_common_mode(loco.right[a], run_id, right_shared);
  if (own_scale) {
    difference = with_shared_shapes(difference, run_id, common);
    left = with_shared_shapes(left, run_id, common);
    right = with_shared_shapes(right, run_id, common);
  }
  return drift_candidates(difference, left, right);
}

double largest_size(const DriftCandidates& found) {
  double size = 0.0;
  for (const auto& f : {found.in_difference, found.in_sum}) {
    if (f) size = std::max(size, f->size_mm);
  }
  return size;
}

TEST(WearCommonMode, TheSharedWanderIsTakenAwayAtEachAxlesOwnScale) {
  const Locomotive loco = locomotive(-1);
  const CommonMode common = locomotive_common_mode(loco.axles);
  // The fastest-wearing axle carries more of the route's wander than the median: at
  // coefficient 1 what is left is a bend a drift fits, well past what a drift must reach ...
  const DriftCandidates at_one = candidates(loco, common, kAxles - 1, false);
  EXPECT_GT(largest_size(at_one), 2.0 * kMinDriftMm) << largest_size(at_one);
  // ... at its own scale, nothing a drift could be.
  for (int a = 0; a < kAxles; ++a) {
    const DriftCandidates own = candidates(loco, common, a, true);
    EXPECT_LT(largest_size(own), kMinDriftMm) << "axle " << a + 1;
    EXPECT_FALSE(flagged_drift(own, LocomotiveBar{}).has_value()) << "axle " << a + 1;
  }
}

TEST(WearCommonMode, ADriftingSensorStillStandsOut) {
  const Locomotive loco = locomotive(2);
  const CommonMode common = locomotive_common_mode(loco.axles);
  std::vector<DriftCandidates> axles;
  for (int a = 0; a < kAxles; ++a) axles.push_back(candidates(loco, common, a, true));
  const LocomotiveBar bar = locomotive_bar(axles);
  for (int a = 0; a < kAxles; ++a) {
    const auto found = flagged_drift(axles[a], bar);
    EXPECT_EQ(found.has_value(), a == 2) << "axle " << a + 1;
    if (found) {
      EXPECT_FALSE(found->left);
      EXPECT_NEAR(found->rate_mm_per_day, 0.01, 0.002);
    }
  }
}

}  // namespace
}  // namespace flange::host
