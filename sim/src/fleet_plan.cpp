// SPDX-License-Identifier: MIT
#include "fleet_plan.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>

#include "gaussian_source.h"
#include "locomotive_wheels.h"
#include "sim_error.h"

namespace flange::sim {
namespace {

// Streams of the seed, one per kind of draw, so that adding a locomotive or a day leaves the
// others' draws as they were.
constexpr std::uint64_t kDriftStream = 1;
constexpr std::uint64_t kLocomotiveStream = 100;
constexpr std::uint64_t kWheelStream = 10000;
constexpr double kDaysPerYear = 365.25;
constexpr int kHottestDayOfYear = 196;  // mid-July

double uniform_in(GaussianSource& draws, double low, double high) {
  return low + (high - low) * draws.uniform();
}

void check_settings(const FleetSettings& settings) {
  if (settings.locomotives < 1 || settings.locomotives > kMaxFleetLocomotives) {
    throw BadArgument(
        fmt::format("--locomotives: {} is outside its valid range: a whole number 1 "
                    "to {}",
                    settings.locomotives, kMaxFleetLocomotives));
  }
  if (settings.days < 1 || settings.days > kMaxFleetDays) {
    throw BadArgument(fmt::format("--days: {} is outside its valid range: a whole number 1 to {}",
                                  settings.days, kMaxFleetDays));
  }
}

int day_of_year(int day) {
  using namespace std::chrono;
  const year_month_day date{sys_days{days{day}}};
  return static_cast<int>((sys_days{date} - sys_days{date.year() / January / 1}).count());
}

std::vector<double> seasonal_ambient(const FleetSettings& settings, const FleetDraws& draws) {
  std::vector<double> ambient;
  for (int day = 0; day < settings.days; ++day) {
    const double phase = 2.0 * std::numbers::pi *
                         (day_of_year(settings.start_day + day) - kHottestDayOfYear) / kDaysPerYear;
    ambient.push_back(draws.ambient_mean_c + draws.ambient_amplitude_c * std::cos(phase));
  }
  return ambient;
}

WheelTruth draw_wheel(const FleetSettings& settings, const FleetDraws& draws, int locomotive,
                      int channel) {
  GaussianSource source(derive_seed(
      settings.seed, kWheelStream + static_cast<std::uint64_t>(locomotive * kMaxWheels + channel)));
  const bool left = wheel_position(channel).side == WheelSide::kLeft;
  WheelTruth wheel;
  wheel.channel = channel;
  wheel.wear_rate_mm_per_1000km =
      left ? uniform_in(source, draws.left_rate_low, draws.left_rate_high)
           : uniform_in(source, draws.right_rate_low, draws.right_rate_high);
  wheel.initial_wear_mm = uniform_in(source, draws.initial_wear_low_mm, draws.initial_wear_high_mm);
  return wheel;
}

// The day's wear of every wheel at the start of its service, after the depot's work that day.
void wear_over_days(LocomotiveTruth& loco, const FleetDraws& draws) {
  std::vector<double> wear;
  for (const WheelTruth& wheel : loco.wheels) wear.push_back(wheel.initial_wear_mm);
  for (std::size_t day = 0; day < loco.day_km.size(); ++day) {
    const bool depot_day = loco.day_km[day] == 0.0;
    for (int axle = 0; depot_day && axle < kLocomotiveAxles; ++axle) {
      const auto left = static_cast<std::size_t>(2 * axle);
      if (std::max(wear[left], wear[left + 1]) < draws.depot_reprofile_wear_mm) continue;
      for (const std::size_t c : {left, left + 1}) {
        wear[c] = 0.0;
        loco.wheels[c].reprofiled_days.push_back(static_cast<int>(day));
      }
    }
    loco.wear_mm.push_back(wear);
    for (std::size_t c = 0; c < wear.size(); ++c) {
      wear[c] += loco.wheels[c].wear_rate_mm_per_1000km * loco.day_km[day] / 1000.0;
    }
  }
}

LocomotiveTruth draw_locomotive(const FleetSettings& settings, const FleetDraws& draws,
                                int locomotive) {
  LocomotiveTruth loco;
  loco.name = fmt::format("L{:02d}", locomotive + 1);
  GaussianSource days(
      derive_seed(settings.seed, kLocomotiveStream + static_cast<std::uint64_t>(locomotive)));
  for (int day = 0; day < settings.days; ++day) {
    const bool depot = days.uniform() < draws.depot_day_chance;
    const double km = uniform_in(days, draws.min_day_km, draws.max_day_km);
    loco.day_km.push_back(depot ? 0.0 : km);
  }
  for (int channel = 0; channel < kMaxWheels; ++channel) {
    loco.wheels.push_back(draw_wheel(settings, draws, locomotive, channel));
  }
  wear_over_days(loco, draws);
  return loco;
}

// One sensor drifts, or two (even odds), on distinct wheels anywhere in the fleet, from a day in
// the first third of the period, up or down.
std::vector<SensorDrift> draw_drifts(const FleetSettings& settings, const FleetDraws& draws) {
  GaussianSource source(derive_seed(settings.seed, kDriftStream));
  const int count = source.uniform() < 0.5 ? 1 : 2;
  const int wheels = settings.locomotives * kMaxWheels;
  std::vector<SensorDrift> drifts;
  while (static_cast<int>(drifts.size()) < std::min(count, wheels)) {
    const int wheel = std::min(wheels - 1, static_cast<int>(source.uniform() * wheels));
    SensorDrift drift;
    drift.locomotive = wheel / kMaxWheels;
    drift.channel = wheel % kMaxWheels;
    drift.start_day = static_cast<int>(source.uniform() * (settings.days / 3));
    const double rate =
        uniform_in(source, draws.drift_rate_low_v_per_day, draws.drift_rate_high_v_per_day);
    drift.rate_v_per_day = source.uniform() < 0.5 ? -rate : rate;
    const bool taken = std::any_of(drifts.begin(), drifts.end(), [&](const SensorDrift& d) {
      return d.locomotive == drift.locomotive && d.channel == drift.channel;
    });
    if (!taken) drifts.push_back(drift);
  }
  return drifts;
}

}  // namespace

FleetTruth plan_fleet(const FleetSettings& settings, const FleetDraws& draws) {
  check_settings(settings);
  FleetTruth truth;
  truth.settings = settings;
  truth.draws = draws;
  truth.ambient_c = seasonal_ambient(settings, draws);
  for (int locomotive = 0; locomotive < settings.locomotives; ++locomotive) {
    truth.locomotives.push_back(draw_locomotive(settings, draws, locomotive));
  }
  truth.drifts = draw_drifts(settings, draws);
  return truth;
}

const SensorDrift* drift_of(const FleetTruth& truth, int locomotive, int channel) {
  for (const SensorDrift& drift : truth.drifts) {
    if (drift.locomotive == locomotive && drift.channel == channel) return &drift;
  }
  return nullptr;
}

std::string iso_date(int day) {
  using namespace std::chrono;
  const year_month_day date{sys_days{days{day}}};
  return fmt::format("{:04d}-{:02d}-{:02d}", static_cast<int>(date.year()),
                     static_cast<unsigned>(date.month()), static_cast<unsigned>(date.day()));
}

}  // namespace flange::sim
