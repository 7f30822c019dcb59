// SPDX-License-Identifier: MIT
// The rtl engine of `flange run`: the Verilated core of the coefficient set, in its runner
// process (tb/stream_run.h), checked against the bit-accurate model on every output.
#pragma once

#include <filesystem>
#include <memory>

#include "filter_engine.h"

namespace flange::host {

// Builds the set's runner on first use (verilated_runner.h) and starts it. Throws
// std::invalid_argument (bad set) or std::runtime_error (build or start failed).
std::unique_ptr<FilterEngine> make_rtl_engine(const std::filesystem::path& filter_json,
                                              int channel = 0);

}  // namespace flange::host
