// SPDX-License-Identifier: MIT
// How the blind check on another bench reality (alt, third) shows its pairs: what both realities'
// reports share, their classes named against a truth sized by the noise.
#pragma once

#include <string>

#include "blind_check.h"
#include "blind_report.h"

namespace flange::diagnose {

// The style of `flange diagnose --selftest --reality REALITY` with these aims and the truth
// column titled `truth_title`; the caller adds its own kind lines, case JSON and tables.
BlindStyle pair_reality_style(const std::string& reality, const std::string& truth_title,
                              const BlindAims& aims, const SelftestOptions& options);

}  // namespace flange::diagnose
