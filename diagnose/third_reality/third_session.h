// SPDX-License-Identifier: MIT
// One session of the third bench rendered into the recording format's columns: the logger's
// rows (logger_timeline.h), the temperature channel and the voltage channel each passed through
// the chain at their own instants (the voltage channel later when skewed), the reference column
// the micrometer at the row's instant, every number rounded to the format's six decimals.
#pragma once

#include <vector>

#include "third_effect.h"
#include "third_session_plan.h"

namespace flange::third_reality {

struct ThirdRecording {
  std::vector<double> t_s, clearance_mm, temp_c, voltage_v;
  std::size_t dropped = 0;  // rows the logger lost
  std::size_t size() const { return t_s.size(); }
};

// `effects` in chain order (third_classes() order). `with_noise` false: no voltage or
// temperature noise and a perfect logger (every row, exact stamps), used to size effects.
ThirdRecording render_session(const SessionPlan& plan, const std::vector<EffectDraw>& effects,
                              bool with_noise);

// What an ideal twin sees of a recording: its voltage less the ideal sensor's at its clearance
// and temperature.
std::vector<double> ideal_twin_gap(const ThirdRecording& recording);

double six_decimals(double value);

}  // namespace flange::third_reality
