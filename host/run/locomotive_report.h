// SPDX-License-Identifier: MIT
// The HTML report of `flange run --manifest`: which wheel is the worst at a glance, and each
// channel's own run report one click away (plots drawn by gnuplot).
#pragma once

#include <filesystem>

#include "locomotive_run.h"

namespace flange::host {

// Writes DIR/index.html: the per-channel table with the worst wheel marked, the filtered
// clearance of every wheel as small multiples (clearance.svg: one panel per wheel, axles down,
// left and right across, warning and critical levels drawn) and every channel's run summary;
// and each channel's own run report (write_run_report) in DIR/channel_XX/.
void write_locomotive_report(const std::filesystem::path& dir, const LocomotiveRun& run);

}  // namespace flange::host
