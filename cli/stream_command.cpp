// SPDX-License-Identifier: MIT
#include "stream_command.h"

#include <iterator>
#include <ostream>
#include <stdexcept>
#include <vector>

#include "cli.h"
#include "input_error.h"
#include "serial_port.h"

namespace flange::cli {

CLI::App* add_stream_command(CLI::App& app, host::StreamSettings& options) {
  CLI::App* cmd = app.add_subcommand(
      "stream", "Stream a recording through the Basys-3 board's filter over its serial port");
  cmd->add_option("--port", options.port, "serial device of the board, e.g. /dev/ttyUSB1")
      ->required();
  cmd->add_option("--input", options.input, "recording CSV (t_s,clearance_mm,temp_c,voltage_v)")
      ->required();
  cmd->add_option("--calibration", options.calibration,
                  "model.json from flange calibrate (default: the thesis's eq. 3.14)");
  cmd->add_option("--out", options.out,
                  "output CSV: t_s,clearance_raw_mm,word_in,word_out,clearance_filt_mm,status")
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
  return cmd;
}

int run_stream_command(const host::StreamSettings& options, std::ostream& out, std::ostream& err) {
  try {
    out << host::stream_summary_line(host::stream_recording(options)) << "\n";
    return kExitOk;
  } catch (const host::InputError& error) {
    err << "flange stream: " << error.what() << "\n";
    return kExitBadArgument;
  } catch (const std::runtime_error& error) {
    err << "flange stream: " << error.what() << "\n";
    return kExitFailure;
  }
}

}  // namespace flange::cli
