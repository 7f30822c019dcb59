// SPDX-License-Identifier: MIT
#include "synthetic_accelerating_fleet.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

namespace flange::testing {
namespace {

constexpr double kGapMm = 2.0;          // the clearance of a new flange (the sensor's setting)
constexpr double kWarningWearMm = 6.0;  // the default warning clearance (8 mm) less the gap

}  // namespace

SyntheticFleet synthetic_accelerating_fleet(double b, std::uint32_t seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> km_of_day(150.0, 750.0), base_rate(0.03, 0.12),
      start_wear(0.5, 4.4);
  std::normal_distribution<double> noise(0.0, 0.01);
  SyntheticFleet fleet;
  for (int loco = 1; loco <= 5; ++loco) {
    const std::string name = "L0" + std::to_string(loco);
    std::vector<host::WheelHistory> wheels;
    std::vector<double> wear, rate, wear_at_last_run;
    for (int axle = 1; axle <= 6; ++axle) {
      for (const char* side : {"left", "right"}) {
        wheels.push_back({{name, axle, side, static_cast<int>(wheels.size())}, {}, {}});
        wear.push_back(start_wear(random));
        wear_at_last_run.push_back(wear.back());
        rate.push_back(base_rate(random) / 1000.0);
      }
    }
    double odometer = 0.0;
    for (int day = 0; day < 120; ++day) {
      const double t = 20454.0 + day + 0.25;
      for (std::size_t w = 0; w < wheels.size(); w += 2) {
        if (std::max(wear[w], wear[w + 1]) <= 4.6) continue;
        for (std::size_t s = w; s < w + 2; ++s) {
          wear[s] = 0.05;
          wheels[s].maintenance.push_back({"", t - 0.1, odometer, "reprofile"});
        }
      }
      if (day % 6 == 5) continue;
      for (std::size_t w = 0; w < wheels.size(); ++w) {
        wheels[w].runs.push_back(
            {loco * 1000 + day, "", t, odometer, kGapMm + wear[w] + noise(random)});
        wear_at_last_run[w] = wear[w];
      }
      const double km = km_of_day(random);
      odometer += km;
      // The day's km in small steps, so the wear law is followed closely.
      for (std::size_t w = 0; w < wheels.size(); ++w) {
        for (int step = 0; step < 10; ++step) {
          wear[w] += rate[w] * std::exp(b * wear[w]) * km / 10.0;
        }
      }
    }
    // The km from the last run to the warning wear, from the wear at that run.
    for (std::size_t w = 0; w < wheels.size(); ++w) {
      const double gap = kWarningWearMm - wear_at_last_run[w];
      const double r_now = rate[w] * std::exp(b * wear_at_last_run[w]);
      fleet.true_km_to_warning.push_back(b == 0.0 ? gap / r_now
                                                  : -std::expm1(-b * gap) / (b * r_now));
    }
    fleet.histories.insert(fleet.histories.end(), wheels.begin(), wheels.end());
  }
  return fleet;
}

}  // namespace flange::testing
