// SPDX-License-Identifier: MIT
// One co-simulation run as `flange cosim` does it: a stimulus streamed back to back through the
// Verilated core and the model, every pin compared in every cycle, one summary line.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "filter_json.h"
#include "iir_core_dut.h"
#include "stimulus.h"

namespace flange::tb {

struct CosimOptions {
  std::filesystem::path coeffs;  // filter.json of the set the core was built for
  std::size_t samples = 10000;   // >= 1 (a FILE stimulus gives at most its own rows)
  std::uint64_t seed = 1;        // for random and fullscale
  // random (uniform, half scale), fullscale (uniform, full range), sweep (log sine sweep from
  // fc / 20 to 0.49 fs at 0.7 of full scale), step (half scale), impulse (full scale), or the
  // path of a CSV file: one integer sample (LSB) per line in the first column; lines starting
  // with '#' and a non-numeric header line are skipped.
  std::string stimulus = "random";
  std::optional<std::filesystem::path> trace;  // FST waveform file
};

// The samples `options` asks for. Throws std::invalid_argument (one line, naming the file and
// line for a CSV) on an unknown kind, an unreadable file or a sample outside the D-bit range.
std::vector<std::int32_t> cosim_samples(const CosimOptions& options,
                                        const model::CoreConfig& config,
                                        const model::FloatDesign& design);

using DutFactory = std::function<std::unique_ptr<Dut>(const std::filesystem::path& fst_path)>;

// Runs the co-simulation and prints the first mismatch (if any) and then exactly one line:
//   cosim: N samples, M mismatches, C cycles/sample, L cycles latency[, K channels in turn]
// A core with K > 1 channels gets sample i on channel i mod K.
// where M counts the cycles in which some output pin differed. Returns 0, or 1 on a mismatch or
// an RTL assertion. Throws std::invalid_argument / FilterJsonError on bad input.
int run_cosim(const CosimOptions& options, const DutFactory& make, std::ostream& out,
              std::ostream& err);

}  // namespace flange::tb
