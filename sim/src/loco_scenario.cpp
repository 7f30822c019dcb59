// SPDX-License-Identifier: MIT
#include "loco_scenario.h"

namespace flange::sim {

LocoScenario::LocoScenario(const LocoRun& run, double fs_hz, double duration_s)
    : locomotive_(run, 1, fs_hz, duration_s) {}

}  // namespace flange::sim
