// SPDX-License-Identifier: MIT
#include "micrometer_protocols.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace flange::alt_reality {
namespace {

// A move that starts and stops smoothly: a half cosine from 0 to 1.
double smooth_progress(double u) {
  return 0.5 - 0.5 * std::cos(std::numbers::pi * std::clamp(u, 0.0, 1.0));
}

double random_positions(const MicrometerProtocol& p, double t_s) {
  const double slot_s = p.move_s + p.dwell_s;
  const auto last = static_cast<long>(p.positions_mm.size()) - 1;
  const long k = std::clamp(static_cast<long>(std::floor(t_s / slot_s)), 0L, last);
  const double to = p.positions_mm[static_cast<std::size_t>(k)];
  if (k == 0) return to;
  const double from = p.positions_mm[static_cast<std::size_t>(k - 1)];
  return from + (to - from) * smooth_progress((t_s - static_cast<double>(k) * slot_s) / p.move_s);
}

double motorised_sweep(const MicrometerProtocol& p, double t_s) {
  const double mid = 0.5 * (p.low_mm + p.high_mm), amplitude = 0.5 * (p.high_mm - p.low_mm);
  return mid + amplitude * std::sin(2.0 * std::numbers::pi * t_s / p.period_s + p.phase);
}

// Climbs low, low + step, ... up to high, then moves back to low in one move, and again.
double sawtooth_staircase(const MicrometerProtocol& p, double t_s) {
  const int levels = static_cast<int>(std::floor((p.high_mm - p.low_mm) / p.step_mm)) + 1;
  const double slot_s = p.move_s + p.dwell_s;
  const auto k = static_cast<long>(std::floor(t_s / slot_s));
  const auto level = [&](long i) { return p.low_mm + p.step_mm * static_cast<double>(i % levels); };
  if (k == 0) return level(0);
  const double from = level(k - 1), to = level(k);
  return from + (to - from) * smooth_progress((t_s - static_cast<double>(k) * slot_s) / p.move_s);
}

}  // namespace

std::string micrometer_kind_name(MicrometerKind kind) {
  switch (kind) {
    case MicrometerKind::kRandomPositions:
      return "random_positions";
    case MicrometerKind::kMotorisedSweep:
      return "motorised_sweep";
    case MicrometerKind::kSawtoothStaircase:
      return "sawtooth_staircase";
  }
  return "?";
}

MicrometerProtocol draw_micrometer(MicrometerKind kind, double duration_s, AltRandom& random) {
  MicrometerProtocol p;
  p.kind = kind;
  p.low_mm = random.uniform(1.5, 2.5);
  p.high_mm = random.uniform(8.5, 10.0);
  p.step_mm = random.uniform(0.5, 1.25);
  p.dwell_s = random.uniform(10.0, 40.0);
  p.move_s = random.uniform(2.0, 6.0);
  p.period_s = random.uniform(90.0, 400.0);
  p.phase = random.uniform(-std::numbers::pi, std::numbers::pi);
  if (kind == MicrometerKind::kRandomPositions) {
    // Positions on the micrometer's 0.25 mm marks, one per slot of the session.
    const auto slots = static_cast<std::size_t>(duration_s / (p.move_s + p.dwell_s)) + 2;
    const int marks = static_cast<int>(std::floor((p.high_mm - p.low_mm) / 0.25)) + 1;
    for (std::size_t i = 0; i < slots; ++i) {
      p.positions_mm.push_back(p.low_mm + 0.25 * random.index(marks));
    }
  }
  return p;
}

double micrometer_mm(const MicrometerProtocol& protocol, double t_s) {
  switch (protocol.kind) {
    case MicrometerKind::kRandomPositions:
      return random_positions(protocol, std::max(t_s, 0.0));
    case MicrometerKind::kMotorisedSweep:
      return motorised_sweep(protocol, std::max(t_s, 0.0));
    case MicrometerKind::kSawtoothStaircase:
      return sawtooth_staircase(protocol, std::max(t_s, 0.0));
  }
  return protocol.low_mm;
}

nlohmann::json micrometer_json(const MicrometerProtocol& p) {
  nlohmann::json j = {
      {"kind", micrometer_kind_name(p.kind)}, {"low_mm", p.low_mm}, {"high_mm", p.high_mm}};
  switch (p.kind) {
    case MicrometerKind::kRandomPositions:
      j["dwell_s"] = p.dwell_s;
      j["move_s"] = p.move_s;
      j["positions_mm"] = p.positions_mm;
      break;
    case MicrometerKind::kMotorisedSweep:
      j["period_s"] = p.period_s;
      j["phase_rad"] = p.phase;
      break;
    case MicrometerKind::kSawtoothStaircase:
      j["step_mm"] = p.step_mm;
      j["dwell_s"] = p.dwell_s;
      j["move_s"] = p.move_s;
      break;
  }
  return j;
}

}  // namespace flange::alt_reality
