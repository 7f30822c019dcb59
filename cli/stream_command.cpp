// SPDX-License-Identifier: MIT
#include "stream_command.h"

#include <filesystem>
#include <iterator>
#include <ostream>
#include <stdexcept>
#include <vector>

#include "board_link.h"
#include "cli.h"
#include "input_error.h"
#include "locomotive_manifest.h"
#include "locomotive_run.h"
#include "serial_port.h"

namespace flange::cli {

CLI::App* add_stream_command(CLI::App& app, StreamOptions& all) {
  host::StreamSettings& options = all.single;
  CLI::App* cmd = app.add_subcommand(
      "stream", "Stream a recording through the Basys-3 board's filter over its serial port");
  cmd->add_option("--port", options.port, "serial device of the board, e.g. /dev/ttyUSB1")
      ->required();
  CLI::Option* input = cmd->add_option("--input", options.input,
                                       "recording CSV (t_s,clearance_mm,temp_c,voltage_v)");
  CLI::Option* manifest = cmd->add_option(
      "--manifest", all.manifest,
      "locomotive.json: every channel it names on its own channel of the board, interleaved in "
      "time (docs/locomotive.md)");
  input->excludes(manifest);
  cmd->add_option("--coeffs", all.coeffs,
                  "with --manifest: the board's filter.json; every reply is checked against the "
                  "model")
      ->needs(manifest);
  cmd->add_option("--calibration", options.calibration,
                  "model.json from flange calibrate (default: the thesis's eq. 3.14)");
  cmd->add_option("--out", options.out,
                  "output CSV: t_s,clearance_raw_mm,word_in,word_out,clearance_filt_mm,status; "
                  "with --manifest a folder for channel_XX.csv")
      ->required();
  cmd->add_option("--baud", options.baud,
                  "baud rate: the bitstream's, 100 MHz / ClksPerBit (115200, 921600, ...)")
      ->default_val(options.baud)
      ->check(CLI::IsMember(
          std::vector<int>(std::begin(host::kSerialBauds), std::end(host::kSerialBauds))));
  cmd->add_option("--timeout-ms", options.timeout_ms, "wait for each reply (1-60000 ms)")
      ->default_val(options.timeout_ms)
      ->check(CLI::Range(1, 60000));
  cmd->add_option("--retries", options.retries, "send a request again this often (0-100)")
      ->default_val(options.retries)
      ->check(CLI::Range(0, 100));
  cmd->add_option("--window", options.window,
                  "requests in flight (1-32; 1: stop-and-wait; docs/board.md, \"Windowed "
                  "session\")")
      ->default_val(options.window)
      ->check(CLI::Range(1, host::kMaxWindow));
  return cmd;
}

namespace {

// Every channel of the manifest: its recording in, channel_XX.csv out in the --out folder.
host::ChannelStreamSettings manifest_settings(const StreamOptions& options) {
  const host::LocomotiveManifest manifest = host::load_locomotive_manifest(options.manifest);
  host::ChannelStreamSettings settings;
  settings.port = options.single.port;
  settings.calibration = options.single.calibration;
  settings.coeffs = options.coeffs;
  settings.source = options.manifest;
  settings.link = {options.single.baud, options.single.timeout_ms, options.single.retries,
                   options.single.window};
  settings.on_port_setup = options.single.on_port_setup;
  const std::filesystem::path out_dir = options.single.out;
  std::filesystem::create_directories(out_dir);
  for (const host::ManifestChannel& channel : manifest.channels) {
    settings.channels.push_back({channel.channel, channel.path.string(),
                                 (out_dir / host::channel_file_name(channel.channel)).string(),
                                 channel.calibration_path.string()});
  }
  return settings;
}

}  // namespace

int run_stream_command(const StreamOptions& options, std::ostream& out, std::ostream& err) {
  if (options.manifest.empty() && options.single.input.empty()) {
    throw host::InputError("give --input (one recording) or --manifest (a locomotive)");
  }
  StreamOptions said = options;
  said.single.on_port_setup = [&err](const std::string& line) {
    err << "flange stream: " << line << "\n";
  };
  const host::StreamCounts counts = said.manifest.empty()
                                        ? host::stream_recording(said.single)
                                        : host::stream_channel_recordings(manifest_settings(said));
  out << host::stream_summary_line(counts) << "\n";
  if (counts.checked && counts.mismatches > 0) return kExitFailure;
  return kExitOk;
}

}  // namespace flange::cli
