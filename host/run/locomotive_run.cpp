// SPDX-License-Identifier: MIT
#include "locomotive_run.h"

#include <fmt/format.h>

#include <system_error>

#include "filter_json.h"
#include "input_error.h"

namespace flange::host {
namespace {

// The same file under two names (a relative and an absolute path, a symbolic link) compares
// equal once both are canonical; a file not yet written compares by its folder.
bool same_file(const std::filesystem::path& a, const std::filesystem::path& b) {
  std::error_code error;
  const std::filesystem::path ca = std::filesystem::weakly_canonical(a, error);
  if (error) return false;
  const std::filesystem::path cb = std::filesystem::weakly_canonical(b, error);
  return !error && ca == cb;
}

// Refuses an output folder that would overwrite any channel's input before anything is written.
void check_outputs_spare_inputs(const LocomotiveManifest& manifest,
                                const std::filesystem::path& out_dir) {
  for (const ManifestChannel& output : manifest.channels) {
    const std::filesystem::path out_csv = out_dir / channel_file_name(output.channel);
    for (const ManifestChannel& input : manifest.channels) {
      if (same_file(out_csv, input.path)) {
        throw InputError(fmt::format(
            "--out {}: its {} would overwrite channel {}'s input {} (from {}); choose another "
            "folder",
            out_dir.string(), channel_file_name(output.channel), input.channel, input.path.string(),
            manifest.path));
      }
    }
  }
}

// Channels of the core the set was designed for (1 for an ordinary set).
int core_channel_count(const std::string& coeffs) {
  try {
    return model::load_core_config(coeffs).num_channels;
  } catch (const model::FilterJsonError& error) {
    throw InputError(error.what());
  }
}

}  // namespace

LocomotiveRun run_locomotive(const LocomotiveManifest& manifest, const RunOptions& shared,
                             const std::optional<std::filesystem::path>& out_dir,
                             bool keep_trace) {
  LocomotiveRun run;
  run.manifest = manifest;
  run.out_dir = out_dir;
  if (out_dir) {
    check_outputs_spare_inputs(manifest, *out_dir);
    std::filesystem::create_directories(*out_dir);
  }
  const int core_channels = core_channel_count(shared.coeffs);
  for (const ManifestChannel& channel : manifest.channels) {
    if (core_channels > 1 && channel.channel >= core_channels) {
      throw InputError(fmt::format("{}: channel {} ({}): {} has channels 0 to {} only",
                                   manifest.path, channel.channel,
                                   channel.path.filename().string(), shared.coeffs,
                                   core_channels - 1));
    }
  }
  for (const ManifestChannel& channel : manifest.channels) {
    ChannelRun& channel_run = run.channels.emplace_back();
    channel_run.channel = channel;
    channel_run.options = shared;
    channel_run.options.input = channel.path.string();
    // The wheel's own calibration when the manifest names one, else the command's.
    if (!channel.calibration.empty()) {
      channel_run.options.calibration = channel.calibration_path.string();
    }
    // A set with a channel per sensor filters each on its own channel; a one-channel set is the
    // same filter for every sensor.
    channel_run.options.channel = core_channels > 1 ? channel.channel : 0;
    channel_run.options.out_csv.reset();
    channel_run.options.report_dir.reset();
    if (out_dir)
      channel_run.options.out_csv = (*out_dir / channel_file_name(channel.channel)).string();
    channel_run.summary =
        run_pipeline(channel_run.options, out_dir || keep_trace ? &channel_run.trace : nullptr);
  }
  return run;
}

}  // namespace flange::host
