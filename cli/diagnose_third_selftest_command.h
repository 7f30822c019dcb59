// SPDX-License-Identifier: MIT
// `flange diagnose --selftest --reality third [--pairs N] [--seed S]`: the blind check on the
// third reality (diagnose/third_reality/, scored by diagnose/alt_check/). Prints the seed, one
// row per pair, the tables by class and by number of true classes and the aims; with
// --out writes DIR/selftest.json and DIR/selftest.md, and with --case K the pair's two sessions
// and its truth sidecar.
#pragma once

#include <iosfwd>

#include "diagnose_selftest_command.h"

namespace flange::cli {

// 0 when every aim is met, 1 when one is missed; throws std::runtime_error when a file cannot be
// written (1) and host::InputError on a bad argument (2).
int run_third_selftest_command(const SelftestCommandOptions& options, std::ostream& out);

}  // namespace flange::cli
