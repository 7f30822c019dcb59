// SPDX-License-Identifier: MIT
// One session of the alternative bench rendered into the recording format's columns: the
// voltage channel and the temperature channel each pass the chain at their own sampling
// instants; the reference column is the micrometer at the stamped time. Every number is
// rounded to the recording format's six decimals, so what is in memory is what a CSV holds.
#pragma once

#include <vector>

#include "alt_effect.h"
#include "alt_session_plan.h"

namespace flange::alt_reality {

struct AltRecording {
  std::vector<double> t_s, clearance_mm, temp_c, voltage_v;
  std::size_t size() const { return t_s.size(); }
};

// `effects` in the order they act (alt_classes() order). `with_noise` false: the noise-free
// chain (voltage and temperature noise off), used to size effects.
AltRecording render_session(const SessionPlan& plan, const std::vector<AltEffectDraw>& effects,
                            bool with_noise);

// The recording format's six decimals.
double to_six_decimals(double value);

}  // namespace flange::alt_reality
