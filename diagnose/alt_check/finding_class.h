// SPDX-License-Identifier: MIT
// The effect class (alternative reality's vocabulary, alt_classes.h) that a finding of the
// diagnosis names. The library's effects map one to one, except that the sign of a lag or a
// skew says which channel is late: thermal_lag with tau_s > 0 is the sensor's own lag, with
// tau_s < 0 a lagging temperature reading; channel_skew with skew_s < 0 is a late voltage
// channel, with skew_s > 0 a late temperature channel (a temperature reading that lags).
#pragma once

#include <string>

#include "diagnosis.h"

namespace flange::diagnose {

// "" for a name outside the library.
std::string class_of_finding(const EffectFinding& finding);

}  // namespace flange::diagnose
