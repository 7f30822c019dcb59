// SPDX-License-Identifier: MIT
// What to measure next (docs/diagnose.md, "What to measure next"): for classes the data cannot
// tell apart and parameters they leave undetermined, the smallest sweep of the temperature or of
// the clearance in which the fits found here would differ by more than the held-out score
// resolves, at this recording's noise.
#pragma once

#include <string>
#include <vector>

#include "degenerate_data.h"
#include "parts.h"
#include "selection.h"

namespace flange::diagnose {

// One sentence per pair of classes the data cannot tell apart and per pick with undetermined
// parameters. Two library fits are told apart by a session (identify/hypothetical_session.h) in
// which their replays differ by sqrt(criteria::kScoreResolution) times the noise RMS; a
// parameter is determined by one in which it is no longer undetermined (parameter_resolution.h).
// The sizes hold for the fits found here: an undetermined parameter's true value may need more.
std::vector<std::string> next_measurements(const Parts& parts, const Selection& selection);

}  // namespace flange::diagnose
