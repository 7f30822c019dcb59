// SPDX-License-Identifier: MIT
// The summary `flange run` prints and the HTML report it writes (plots drawn by gnuplot).
#pragma once

#include <filesystem>
#include <string>

#include "run_pipeline.h"

namespace flange::host {

std::string run_summary_text(const RunOptions& options, const RunSummary& summary);

// Writes DIR/index.html with traces.svg, error_by_region.svg, response.svg and spectra.svg.
void write_run_report(const std::filesystem::path& dir, const RunOptions& options,
                      const RunSummary& summary, const RunTrace& trace);

}  // namespace flange::host
