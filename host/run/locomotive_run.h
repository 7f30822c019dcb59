// SPDX-License-Identifier: MIT
// `flange run --manifest`: every channel of a locomotive recording through the run pipeline, one
// after the other and each on its own (its own filter state, thresholds and output file), exactly
// as `flange run --input` runs that channel's file alone.
#pragma once

#include <filesystem>
#include <optional>
#include <vector>

#include "locomotive_manifest.h"
#include "run_pipeline.h"

namespace flange::host {

struct ChannelRun {
  ManifestChannel channel;
  RunOptions options;  // what the channel ran with: the shared options, its input and output
  RunSummary summary;
  RunTrace trace;  // filled when the run writes into a folder (for the report) or keeps traces
};

struct LocomotiveRun {
  LocomotiveManifest manifest;
  std::optional<std::filesystem::path> out_dir;
  std::vector<ChannelRun> channels;  // in channel order
};

// Runs every channel of `manifest` with the options of `shared` (calibration, coeffs, engine,
// thresholds, lenient; its input, out_csv and report_dir are not used); a channel whose manifest
// entry names a calibration uses that one instead of shared.calibration. With `out_dir`, each
// channel's output CSV goes to out_dir/channel_XX.csv (the folder is created). Throws InputError
// (exit status 2) for bad input, naming the channel's file, and when an output would overwrite a
// channel's input; std::runtime_error when a file cannot be written. `keep_trace`: fill each
// channel's trace without an `out_dir` too (a store keeps their reduction).
LocomotiveRun run_locomotive(const LocomotiveManifest& manifest, const RunOptions& shared,
                             const std::optional<std::filesystem::path>& out_dir,
                             bool keep_trace = false);

}  // namespace flange::host
