// SPDX-License-Identifier: MIT
#include "coil_parts.h"

#include <algorithm>
#include <optional>

#include "effect_classes.h"

namespace flange::diagnose {
namespace {

// The skew that makes the voltage channel late among the modelled effects, if any.
std::optional<ChannelDelay> voltage_channel_skew(const std::vector<sim::EffectSettings>& modelled) {
  for (const sim::EffectSettings& effect : modelled) {
    if (const ChannelDelay delay = channel_delay_of(effect); delay.voltage_late()) return delay;
  }
  return std::nullopt;
}

// `series` with its clearance and temperature taken where the voltage was made: |skew(t)| later
// wherever `skew` makes the voltage late (held at the first row before the record began, as the
// twin's skew holds it).
void shift_inputs(RecordingSeries& series, const ChannelDelay& skew) {
  const RecordingSeries recorded = series;
  for (std::size_t i = 0; i < series.size(); ++i) {
    const double at = recorded.t_s[i] + std::min(0.0, skew.skew.at(recorded.t_s[i]));
    series.clearance_mm[i] = interpolate_at(recorded.t_s, recorded.clearance_mm, at);
    series.temp_c[i] = interpolate_at(recorded.t_s, recorded.temp_c, at);
  }
}

}  // namespace

CoilParts::CoilParts(const Parts& parts, const std::vector<sim::EffectSettings>& modelled)
    : parts_(parts) {
  const std::optional<ChannelDelay> voltage_skew = voltage_channel_skew(modelled);
  if (std::none_of(modelled.begin(), modelled.end(), delays_temperature_channel) && !voltage_skew) {
    return;
  }
  auto copies = std::make_unique<Copies>();
  copies->calibration = parts.calibration;
  copies->calibration.temp_c = ambient_from_recorded(parts.calibration, modelled);
  copies->heldout = parts.heldout;
  copies->heldout.temp_c = ambient_from_recorded(parts.heldout, modelled);
  if (voltage_skew) {
    shift_inputs(copies->calibration, *voltage_skew);
    shift_inputs(copies->heldout, *voltage_skew);
  }
  copies->cal_replay = std::make_unique<TwinReplay>(copies->calibration, parts.cal_replay.nominal(),
                                                    parts.cal_replay.age_offset_s());
  copies->ho_replay = std::make_unique<TwinReplay>(copies->heldout, parts.ho_replay.nominal(),
                                                   parts.ho_replay.age_offset_s());
  copies_ = std::move(copies);
}

RecordedPart CoilParts::calibration() const {
  if (!copies_) return parts_.cal();
  return {copies_->calibration, *copies_->cal_replay};
}

RecordedPart CoilParts::heldout() const {
  if (!copies_) return parts_.ho();
  return {copies_->heldout, *copies_->ho_replay};
}

}  // namespace flange::diagnose
