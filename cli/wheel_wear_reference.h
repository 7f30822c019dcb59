// SPDX-License-Identifier: MIT
// `flange run --store` on a locomotive: each wheel's wear and the locomotive's odometer read in
// the light of the depot's maintenance records (flange maintenance, docs/store.md).
//
// A wheel's wear is its clearance at reference conditions less the clearance over its flange
// when new: `new_flange_clearance_mm` (the sensor's setting, 2 mm by default) until the depot
// records a change at the wheel; after the latest one before the run, the reference is the
// wheel's first run after it, where the wear was
//   reprofile        0 (the lathe cut a new flange)
//   sensor_replaced  the wheel's last stored wear before it (the flange did not change; the new
//                    unit's own offset is not wear)
//   wheelset_moved   the last stored wear of the same side on the axle the wheelset came from
//                    (the event's from_axle)
// (with no stored wear to carry over, the new flange's clearance is the reference again).
// The odometer: the reading given plus every recorded reset's reading before the run, so that a
// reset odometer counts on; a reading that would run backwards is refused.
#pragma once

#include <string>

#include "store.h"

namespace flange::cli {

// Fills wear_mm of every wheel of `record` (a locomotive's run with its clearances and
// started_at) from the runs and maintenance events already stored.
void fill_wheel_wear(host::Store& store, host::RunRecord& record, double new_flange_clearance_mm);

// The odometer (km) to store for a run of `locomotive` starting `started_at` whose odometer read
// `reading_km`. Throws host::InputError naming --odometer-km when the result is below the
// locomotive's latest stored run before it (a reset not recorded).
double continuous_odometer(host::Store& store, const host::RunRecord& record, double reading_km);

}  // namespace flange::cli
