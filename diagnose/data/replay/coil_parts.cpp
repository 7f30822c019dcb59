// SPDX-License-Identifier: MIT
#include "coil_parts.h"

#include <algorithm>

#include "effect_classes.h"

namespace flange::diagnose {
namespace {

// How late the modelled effects make the voltage channel (s, <= 0: the voltage at t was made at
// t + shift), or 0.
double voltage_channel_shift_s(const std::vector<sim::EffectSettings>& modelled) {
  for (const sim::EffectSettings& effect : modelled) {
    if (const double shift_s = channel_delay_of(effect).voltage_shift_s; shift_s < 0.0) {
      return shift_s;
    }
  }
  return 0.0;
}

// `series` with its clearance and temperature taken `shift_s` later (held at the first row before
// the record began, as the twin's skew holds it).
void shift_inputs(RecordingSeries& series, double shift_s) {
  const RecordingSeries recorded = series;
  for (std::size_t i = 0; i < series.size(); ++i) {
    series.clearance_mm[i] =
        interpolate_at(recorded.t_s, recorded.clearance_mm, recorded.t_s[i] + shift_s);
    series.temp_c[i] = interpolate_at(recorded.t_s, recorded.temp_c, recorded.t_s[i] + shift_s);
  }
}

}  // namespace

CoilParts::CoilParts(const Parts& parts, const std::vector<sim::EffectSettings>& modelled)
    : parts_(parts) {
  const double voltage_shift_s = voltage_channel_shift_s(modelled);
  if (std::none_of(modelled.begin(), modelled.end(), delays_temperature_channel) &&
      voltage_shift_s == 0.0) {
    return;
  }
  auto copies = std::make_unique<Copies>();
  copies->calibration = parts.calibration;
  copies->calibration.temp_c = ambient_from_recorded(parts.calibration, modelled);
  copies->heldout = parts.heldout;
  copies->heldout.temp_c = ambient_from_recorded(parts.heldout, modelled);
  if (voltage_shift_s != 0.0) {
    shift_inputs(copies->calibration, voltage_shift_s);
    shift_inputs(copies->heldout, voltage_shift_s);
  }
  copies->cal_replay = std::make_unique<TwinReplay>(
      copies->calibration, parts.cal_replay.nominal(), parts.cal_replay.age_offset_s());
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
