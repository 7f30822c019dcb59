// SPDX-License-Identifier: MIT
// What `flange diagnose --selftest --reality alt` shows beyond the harness's report
// (blind_report.h): its seed line and its words and columns (the fitting session's noise, the
// nearest class of an unexplained verdict, the table by class).
#pragma once

#include <string>

#include "alt_selftest.h"
#include "blind_report.h"

namespace flange::diagnose {

// The first line: pairs, seed, what a pair is.
std::string alt_selftest_header(const AltSummary& summary, const SelftestOptions& options);
// The report of a run seeded options.seed: one row per pair (kind, verdict, top/all/nearest,
// shrinks, noise, classes named, the truth), the table by class; selftest.json gives each pair's
// truth as its sidecar does.
BlindStyle alt_selftest_style(const SelftestOptions& options);

}  // namespace flange::diagnose
