// SPDX-License-Identifier: MIT
#include "fleet_day.h"

#include <fmt/format.h>

#include <fstream>
#include <stdexcept>

#include "effect_catalogue.h"
#include "gaussian_source.h"

namespace flange::sim {
namespace {

// Far from the streams plan_fleet draws from (below 10000 + 12 x 100 wheels).
constexpr std::uint64_t kTwinStream = 1u << 20;

}  // namespace

LocoRun fleet_day_run(const FleetTruth& truth, int day, const FleetRecording& recording) {
  LocoRun run;
  run.track.tangent_out_m = recording.route_tangent_out_m;
  run.brakes.ambient_c = truth.ambient_c.at(static_cast<std::size_t>(day));
  return run;
}

std::vector<FlangeWear> fleet_day_flanges(const FleetTruth& truth, int locomotive, int day,
                                          const FleetRecording& recording) {
  const LocomotiveTruth& loco = truth.locomotives.at(static_cast<std::size_t>(locomotive));
  const double recording_km = recording.duration_s * LocoRun{}.track.speed_mps / 1000.0;
  std::vector<FlangeWear> flanges;
  for (const WheelTruth& wheel : loco.wheels) {
    const double wear_mm =
        loco.wear_mm.at(static_cast<std::size_t>(day)).at(static_cast<std::size_t>(wheel.channel));
    flanges.push_back({recording.new_flange_clearance_mm + wear_mm,
                       wheel.wear_rate_mm_per_1000km * recording_km / 1000.0});
  }
  return flanges;
}

TwinConfig fleet_day_twin(const TwinConfig& base, const FleetTruth& truth, int locomotive,
                          int channel, int day) {
  TwinConfig config = base;
  const SensorDrift* drift = drift_of(truth, locomotive, channel);
  if (drift == nullptr || day < drift->start_day) return config;
  config.effects.push_back(
      make_effect_settings("ageing_drift",
                           {{"rate_v_per_day", drift->rate_v_per_day},
                            {"start_age_days", static_cast<double>(day - drift->start_day)}},
                           "fleet drift"));
  return config;
}

std::uint64_t fleet_twin_seed(std::uint64_t seed, int locomotive, int day, int channel) {
  const auto wheel = static_cast<std::uint64_t>(locomotive * kMaxWheels + channel);
  return derive_seed(derive_seed(seed, kTwinStream + wheel), static_cast<std::uint64_t>(day));
}

std::vector<SimulationSummary> simulate_fleet_day(const FleetTruth& truth, int locomotive, int day,
                                                  const FleetRecording& recording,
                                                  const TwinConfig& base,
                                                  const std::filesystem::path& dir) {
  Locomotive loco(fleet_day_run(truth, day, recording),
                  fleet_day_flanges(truth, locomotive, day, recording), recording.fs_hz,
                  recording.duration_s);
  std::vector<SensorTwin> twins;
  std::vector<std::ofstream> files;
  std::vector<std::ostream*> streams;
  for (int c = 0; c < loco.wheels(); ++c) {
    twins.emplace_back(fleet_day_twin(base, truth, locomotive, c, day),
                       fleet_twin_seed(truth.settings.seed, locomotive, day, c));
    const std::filesystem::path path = dir / fmt::format("channel_{:02d}.csv", c);
    files.emplace_back(path, std::ios::binary);
    if (!files.back()) throw std::runtime_error(path.string() + ": cannot write the recording");
  }
  for (std::ofstream& file : files) streams.push_back(&file);
  std::vector<SimulationSummary> summaries = run_locomotive_simulation(loco, twins, streams);
  for (std::size_t c = 0; c < files.size(); ++c) {
    files[c].close();
    if (!files[c]) throw std::runtime_error(fmt::format("{}: writing the recording failed", c));
  }
  return summaries;
}

}  // namespace flange::sim
