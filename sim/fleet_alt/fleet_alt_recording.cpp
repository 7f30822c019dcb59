// SPDX-License-Identifier: MIT
#include "fleet_alt_recording.h"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <stdexcept>

namespace flange::fleet_alt {
namespace {

constexpr std::uint64_t kRecordingStream = 1u << 24;  // + locomotive x days + day
constexpr std::uint64_t kBenchStream = 500;           // + session
constexpr double kVibrationMm = 0.04;                 // the wheel's lateral jitter the shift misses
constexpr double kThermocoupleNoiseC = 0.15;
constexpr double kTwoPi = 2.0 * std::numbers::pi;

std::ofstream open_csv(const std::filesystem::path& path) {
  std::ofstream file(path, std::ios::binary);
  if (!file) throw std::runtime_error(path.string() + ": cannot write the recording");
  file << "t_s,clearance_mm,temp_c,voltage_v\n";
  return file;
}

void close_csv(std::ofstream& file, const std::filesystem::path& path) {
  file.close();
  if (!file) throw std::runtime_error(path.string() + ": writing the recording failed");
}

void write_manifest(const std::filesystem::path& dir, const std::string& generated_by) {
  nlohmann::ordered_json channels = nlohmann::ordered_json::array();
  for (int c = 0; c < kWheels; ++c) {
    channels.push_back({{"channel", c},
                        {"axle", c / 2 + 1},
                        {"side", c % 2 == 0 ? "left" : "right"},
                        {"file", fmt::format("channel_{:02d}.csv", c)}});
  }
  std::ofstream file(dir / "locomotive.json", std::ios::binary);
  file << nlohmann::ordered_json{{"generated_by", generated_by}, {"channels", channels}}.dump(1)
       << "\n";
  file.close();
  if (!file) throw std::runtime_error((dir / "locomotive.json").string() + ": cannot write");
}

// One wheel's sample: the clearance its sensor sees and what the recorder keeps.
struct WheelSample {
  double temp_c = 0.0, voltage_v = 0.0;
};

WheelSample sample_wheel(const WheelOnDay& wheel, double clearance_mm, double coil_c, int day,
                         FleetRandom& random) {
  WheelSample sample;
  sample.temp_c = thermocouple_reading_c(coil_c + kThermocoupleNoiseC * random.normal());
  sample.voltage_v = recorded_voltage(sensor_voltage(wheel.unit, clearance_mm, coil_c, day) +
                                      kNoiseV * random.normal());
  return sample;
}

}  // namespace

double recording_km(const FleetAltTruth& truth, int route) {
  return truth.routes.at(static_cast<std::size_t>(route)).kind.speed_mps *
         truth.settings.recording_s / 1000.0;
}

void write_locomotive_day(const FleetAltTruth& truth, int l, int day,
                          const std::filesystem::path& dir, const std::string& generated_by) {
  const FleetAltSettings& s = truth.settings;
  const LocomotiveDay& today =
      truth.locomotives.at(static_cast<std::size_t>(l)).days.at(static_cast<std::size_t>(day));
  const RouteTrack& track = truth.routes.at(static_cast<std::size_t>(today.route));
  const double ambient = truth.ambient_c.at(static_cast<std::size_t>(day));
  FleetRandom random(s.seed, kRecordingStream + static_cast<std::uint64_t>(l * kMaxDays + day));
  std::array<double, 6> phase{}, phase2{};
  for (int a = 0; a < 6; ++a) {
    phase[static_cast<std::size_t>(a)] = kTwoPi * random.unit();
    phase2[static_cast<std::size_t>(a)] = kTwoPi * random.unit();
  }
  std::filesystem::create_directories(dir);
  std::array<std::ofstream, kWheels> files;
  for (int c = 0; c < kWheels; ++c) files[c] = open_csv(dir / fmt::format("channel_{:02d}.csv", c));
  const auto samples = static_cast<long>(std::floor(s.recording_s * s.fs_hz));
  for (long i = 0; i < samples; ++i) {
    const double t = static_cast<double>(i) / s.fs_hz;
    const double front_m = today.track_start_m + track.kind.speed_mps * t;
    for (int axle = 1; axle <= 6; ++axle) {
      const WheelOnDay& left = today.wheels[static_cast<std::size_t>(2 * axle - 2)];
      const WheelOnDay& right = today.wheels[static_cast<std::size_t>(2 * axle - 1)];
      const double y =
          lateral_shift_mm(track, axle, front_m - axle_offset_m(axle),
                           0.5 * (left.wear_mm + right.wear_mm), phase[axle - 1], phase2[axle - 1]);
      for (int side = 0; side < 2; ++side) {
        const WheelOnDay& wheel = side == 0 ? left : right;
        const double clearance = kNewFlangeClearanceMm + wheel.mount_mm + wheel.wear_mm +
                                 (side == 0 ? -y : y) + kVibrationMm * random.normal();
        const double coil =
            coil_temperature_c(ambient, t, today.parked_rise_c, wheel.coil_offset_c);
        const WheelSample sample = sample_wheel(wheel, clearance, coil, day, random);
        files[static_cast<std::size_t>(2 * axle - 2 + side)]
            << fmt::format("{:.4f},,{:.1f},{:.5f}\n", t, sample.temp_c, sample.voltage_v);
      }
    }
  }
  for (int c = 0; c < kWheels; ++c) close_csv(files[c], dir / fmt::format("channel_{:02d}.csv", c));
  write_manifest(dir, generated_by);
}

void write_bench_session(const FleetAltSettings& settings, int n,
                         const std::filesystem::path& path) {
  FleetRandom random(settings.seed, kBenchStream + static_cast<std::uint64_t>(n));
  SensorUnit unit;
  unit.gain = 1.0 + 0.008 * random.normal();
  unit.zero_mm = 0.05 * random.normal();
  unit.offset_v = 0.03 * random.normal();
  std::ofstream file = open_csv(path);
  constexpr std::array<double, 5> kChamberC = {5.0, 20.0, 35.0, 50.0, 62.0};
  constexpr double kHoldS = 12.0;  // each micrometer setting
  const double fs = settings.fs_hz;
  double t = 0.0;
  for (const double chamber : kChamberC) {
    for (double setting = 1.0; setting <= 11.0 + 1e-9; setting += 0.5) {
      const double micrometer = setting + 0.003 * random.normal();
      for (int k = 0; k < static_cast<int>(kHoldS * fs); ++k, t += 1.0 / fs) {
        const double coil = chamber + 0.4 * std::sin(kTwoPi * t / 600.0);
        const double volts = recorded_voltage(sensor_voltage(unit, micrometer, coil, 0.0) +
                                              kNoiseV * random.normal());
        const double reading = thermocouple_reading_c(coil + kThermocoupleNoiseC * random.normal());
        file << fmt::format("{:.4f},{:.3f},{:.1f},{:.5f}\n", t, setting, reading, volts);
      }
    }
  }
  close_csv(file, path);
}

}  // namespace flange::fleet_alt
