// SPDX-License-Identifier: MIT
#include "locomotive.h"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "scenario.h"

namespace flange::sim {

namespace {

std::vector<FlangeWear> spread_flanges(const LocoRun& run, int wheels) {
  if (wheels < 1 || wheels > kMaxWheels) {
    throw std::out_of_range(
        fmt::format("wheels = {} is outside its valid range 1 to {}", wheels, kMaxWheels));
  }
  const FlangeWear nominal{run.initial_clearance_mm, run.wear_over_run_mm};
  std::vector<FlangeWear> flanges;
  for (int channel = 0; channel < wheels; ++channel) {
    flanges.push_back(flange_wear(nominal, run.spread, channel));
  }
  return flanges;
}

}  // namespace

Locomotive::Locomotive(const LocoRun& run, int wheels, double fs_hz, double duration_s)
    : Locomotive(run, spread_flanges(run, wheels), fs_hz, duration_s) {}

Locomotive::Locomotive(const LocoRun& run, const std::vector<FlangeWear>& flanges, double fs_hz,
                       double duration_s)
    : run_(run),
      fs_hz_(fs_hz),
      duration_s_(duration_s),
      sample_count_(sample_count_for(fs_hz, duration_s)),
      lap_m_(lap_length_m(run.track)),
      heating_(run.brakes),
      flanges_(flanges) {
  const int wheels = static_cast<int>(flanges.size());
  if (wheels < 1 || wheels > kMaxWheels) {
    throw std::out_of_range(
        fmt::format("wheels = {} is outside its valid range 1 to {}", wheels, kMaxWheels));
  }
  const int axles = (wheels + 1) / 2;
  for (int axle = 1; axle <= axles; ++axle) {
    axles_.push_back({axle_offset_m(run.axles, axle), WheelsetLateral(run.wheelset)});
  }
  truth_.resize(static_cast<std::size_t>(wheels));
}

double Locomotive::lateral_force_n(const Axle& axle, double t_s) const {
  // A trailing axle was on the previous lap at the start: the lap repeats.
  double lap_position_m = std::fmod(run_.track.speed_mps * t_s - axle.offset_m, lap_m_);
  if (lap_position_m < 0.0) lap_position_m += lap_m_;
  const WheelsetLateral& wheelset = axle.wheelset;
  const double curve_n = wheelset.supported_mass_kg() * unbalanced_acceleration_mps2(run_.track) *
                         curve_share(run_.track, lap_position_m);
  const double irregularity_n =
      wheelset.mass_kg() * irregularity_acceleration_mps2(run_.track, lap_position_m);
  return curve_n - irregularity_n;
}

// Equal sub-steps no longer than internal_step_s, landing exactly on the sample instant.
void Locomotive::integrate_to(double target_t_s) {
  const double span_s = target_t_s - t_s_;
  if (span_s <= 0.0) return;
  const auto steps = static_cast<std::int64_t>(std::ceil(span_s / run_.internal_step_s - 1e-9));
  const double dt_s = span_s / static_cast<double>(steps);
  for (std::int64_t k = 0; k < steps; ++k) {
    const double t = t_s_ + static_cast<double>(k) * dt_s;
    for (Axle& axle : axles_) {
      const auto force = [this, &axle](double at) { return lateral_force_n(axle, at); };
      axle.wheelset.step(t, dt_s, force);
    }
    heating_.advance(t, dt_s);
  }
  t_s_ = target_t_s;
}

const std::vector<TrueState>& Locomotive::next() {
  const double target_t_s = static_cast<double>(next_sample_++) / fs_hz_;
  integrate_to(target_t_s);
  const double worn_share = duration_s_ > 0.0 ? target_t_s / duration_s_ : 0.0;
  for (std::size_t channel = 0; channel < truth_.size(); ++channel) {
    const WheelPosition position = wheel_position(static_cast<int>(channel));
    const double shift_mm =
        axles_[static_cast<std::size_t>(position.axle - 1)].wheelset.displacement_m() * 1e3;
    const FlangeWear& flange = flanges_[channel];
    // The shift towards the left rail closes the left gap and opens the right one.
    const double base_mm = flange.initial_clearance_mm + flange.wear_over_run_mm * worn_share;
    const double clearance_mm =
        position.side == WheelSide::kLeft ? base_mm - shift_mm : base_mm + shift_mm;
    truth_[channel] = {target_t_s, clearance_mm, heating_.temperature_c()};
  }
  return truth_;
}

double Locomotive::lateral_displacement_mm(int axle) const {
  return axles_.at(static_cast<std::size_t>(axle - 1)).wheelset.displacement_m() * 1e3;
}

}  // namespace flange::sim
