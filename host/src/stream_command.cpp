// SPDX-License-Identifier: MIT
#include "stream_command.h"

#include <fmt/format.h>

#include <array>
#include <chrono>
#include <fstream>
#include <functional>
#include <optional>
#include <ostream>
#include <stdexcept>

#include "board_frame.h"
#include "calibration.h"
#include "fixed_decimals.h"
#include "cli.h"
#include "input_error.h"
#include "recording_csv.h"
#include "sample_scaling.h"
#include "serial_port.h"
#include "thesis_pipeline.h"

namespace flange::host {
namespace {

struct StreamCounts {
  std::uint64_t samples = 0;
  std::uint64_t resent = 0;          // requests sent again after a timeout
  std::uint64_t stray_replies = 0;   // intact replies with another SEQ (late or stale)
  std::uint64_t link_errors = 0;     // replies whose STATUS reports discarded bytes
  std::uint64_t overruns = 0;        // replies whose STATUS reports a dropped frame
  std::uint64_t saturated = 0;       // replies whose STATUS reports clipping
  std::uint64_t bypassed = 0;        // replies with the unfiltered input (sw[0] up)
  std::uint64_t clipped_inputs = 0;  // clearances outside the sample word's range
  std::uint64_t discarded_bytes = 0;
};

class BoardLink {
 public:
  BoardLink(SerialPort& port, const StreamOptions& options) : port_(port), options_(options) {}

  // The reply to (seq, word), sending again on a timeout; throws when the board stays silent.
  board::Reply exchange(std::uint8_t seq, std::int16_t word, StreamCounts& counts) {
    return exchange_frame(board::encode_request(seq, word), seq, counts);
  }
  // Restarts the session: the board resets its filter and forgets the last SEQ.
  void reset_session(std::uint8_t seq, StreamCounts& counts) {
    const board::Reply reply =
        exchange_frame(board::encode_command(seq, board::kCommandReset), seq, counts);
    if (!(reply.status & board::kStatusSessionReset)) {
      throw std::runtime_error("the board on " + port_.device() +
                               " did not confirm the session reset (an older bitstream?)");
    }
  }

 private:
  board::Reply exchange_frame(const std::array<std::uint8_t, board::kRequestBytes>& request,
                              std::uint8_t seq, StreamCounts& counts) {
    const std::chrono::milliseconds timeout(options_.timeout_ms);
    for (int attempt = 0; attempt <= options_.retries; ++attempt) {
      if (attempt > 0) ++counts.resent;
      port_.write_all(request, timeout);
      const auto deadline = std::chrono::steady_clock::now() + timeout;
      while (true) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
            deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) break;
        std::array<std::uint8_t, 64> buffer{};
        const std::size_t n = port_.read_some(buffer, left);
        for (std::size_t i = 0; i < n; ++i) {
          if (std::optional<board::Reply> reply = scanner_.push(buffer[i])) {
            if (reply->seq == seq) {
              counts.discarded_bytes = scanner_.discarded();
              return *reply;
            }
            ++counts.stray_replies;
          }
        }
      }
    }
    throw std::runtime_error(fmt::format(
        "the board on {} does not answer: no reply to sample {} after {} attempt(s) of {} ms (is "
        "the Basys-3 programmed with the flange bitstream, is this its UART port, is the baud "
        "rate {}?)",
        port_.device(), counts.samples, options_.retries + 1, options_.timeout_ms, options_.baud));
  }

 private:
  SerialPort& port_;
  const StreamOptions& options_;
  board::ReplyScanner scanner_;
};

}  // namespace

CLI::App* add_stream_command(CLI::App& app, StreamOptions& options) {
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
  cmd->add_option("--baud", options.baud, "baud rate (the bitstream's: 115200)")
      ->default_val(options.baud);
  cmd->add_option("--timeout-ms", options.timeout_ms, "wait for each reply (1-60000 ms)")
      ->default_val(options.timeout_ms)
      ->check(CLI::Range(1, 60000));
  cmd->add_option("--retries", options.retries, "send a request again this often (0-100)")
      ->default_val(options.retries)
      ->check(CLI::Range(0, 100));
  return cmd;
}

int run_stream_command(const StreamOptions& options, std::ostream& out, std::ostream& err) {
  const auto start = std::chrono::steady_clock::now();
  StreamCounts counts;
  try {
    // Voltage and temperature to clearance: the host's regression stage, as in `flange run`.
    std::function<double(double, double)> clearance_of = eq_3_14;
    if (!options.calibration.empty()) {
      clearance_of = [calibration = load_calibration(options.calibration)](double v, double t) {
        return calibration.estimate(v, t).clearance_mm;
      };
    }
    // The whole recording is checked before the board sees a sample, so a bad row cannot stop
    // a session half-way (a first pass, so memory stays flat).
    {
      RecordingReader check(options.input);
      while (check.next()) {
      }
    }
    RecordingReader reader(options.input);
    std::ofstream csv(options.out, std::ios::binary);
    if (!csv) {
      err << "flange stream: cannot write " << options.out << "\n";
      return kExitFailure;
    }
    SerialPort port(options.port, options.baud);
    port.discard_input();
    BoardLink link(port, options);
    const SampleScaling scaling;
    csv << "t_s,clearance_raw_mm,word_in,word_out,clearance_filt_mm,status\n";
    // A fresh filter, as `flange run` starts with: the outputs then equal the model's.
    link.reset_session(0, counts);
    std::uint8_t seq = 1;
    while (std::optional<RecordingRow> row = reader.next()) {
      const double raw_mm = clearance_of(row->voltage_v, row->temp_c);
      bool clipped = false;
      const auto word = static_cast<std::int16_t>(scaling.to_word(raw_mm, clipped));
      counts.clipped_inputs += clipped ? 1 : 0;
      const board::Reply reply = link.exchange(seq, word, counts);
      ++counts.samples;
      counts.link_errors += (reply.status & board::kStatusLinkError) ? 1 : 0;
      counts.overruns += (reply.status & board::kStatusOverrun) ? 1 : 0;
      counts.saturated += (reply.status & board::kStatusSaturation) ? 1 : 0;
      counts.bypassed += (reply.status & board::kStatusBypass) ? 1 : 0;
      // The Butterworth designs have no leftover gain (1.0): the word is the clearance.
      const double filt_mm = scaling.unit_to_mm(reply.sample / scaling.full_scale());
      csv << fmt::format("{},{},{},{},{},{}\n", row->t_s, fixed6(raw_mm), word, reply.sample,
                         fixed6(filt_mm), reply.status);
      seq = static_cast<std::uint8_t>(seq + 1);
    }
  } catch (const InputError& error) {
    err << "flange stream: " << error.what() << "\n";
    return kExitBadArgument;
  } catch (const std::runtime_error& error) {
    err << "flange stream: " << error.what() << "\n";
    return kExitFailure;
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  out << fmt::format(
      "stream: {} samples in {:.2f} s, {} resent, {} stray replies, {} discarded bytes; board "
      "reported {} link errors, {} overruns, {} saturated, {} bypassed; {} inputs clipped\n",
      counts.samples, seconds, counts.resent, counts.stray_replies, counts.discarded_bytes,
      counts.link_errors, counts.overruns, counts.saturated, counts.bypassed,
      counts.clipped_inputs);
  return kExitOk;
}

}  // namespace flange::host
