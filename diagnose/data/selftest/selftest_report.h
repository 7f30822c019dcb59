// SPDX-License-Identifier: MIT
// What `flange diagnose --selftest` shows of the twin's blind check (diagnose_selftest.h) beyond
// the harness's report (blind_report.h): its header line, its words and columns (the table as
// docs/diagnose_figures.md records it), and a single case's two sessions as recordings.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "blind_report.h"
#include "diagnose_selftest.h"

namespace flange::diagnose {

// The first line: cases, seed, session length and the twin's noise.
std::string selftest_header(const SelftestSummary& summary, std::uint64_t seed, double duration_s);
// The twin's report: one row per case (kind, verdict, top/all correct, shrinks, named effects and
// the truth), no table by class; selftest.json gives `duration_s`, the sessions' length.
BlindStyle selftest_style(double duration_s);
// DIR/case_K_calibration.csv and DIR/case_K_heldout.csv, for `flange diagnose --real ...
// --holdout ...`. Throws std::runtime_error naming a file that cannot be written.
std::vector<std::filesystem::path> write_selftest_recordings(const std::filesystem::path& dir,
                                                             int case_index,
                                                             const SelftestRecordings& recordings);

}  // namespace flange::diagnose
