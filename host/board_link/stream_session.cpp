// SPDX-License-Identifier: MIT
#include "stream_session.h"

#include <fmt/format.h>

#include <array>
#include <chrono>
#include <fstream>
#include <functional>
#include <optional>
#include <stdexcept>

#include "board_frame.h"
#include "calibration.h"
#include "fixed_decimals.h"
#include "recording_csv.h"
#include "sample_scaling.h"
#include "serial_port.h"

namespace flange::host {
namespace {

// One request and its reply at a time, over the port.
class BoardLink {
 public:
  BoardLink(SerialPort& port, const StreamSettings& settings) : port_(port), settings_(settings) {}

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
    const std::chrono::milliseconds timeout(settings_.timeout_ms);
    for (int attempt = 0; attempt <= settings_.retries; ++attempt) {
      if (attempt > 0) ++counts.resent;
      port_.write_all(request, timeout);
      if (std::optional<board::Reply> reply = await_reply(seq, timeout, counts)) return *reply;
    }
    throw std::runtime_error(fmt::format(
        "the board on {} does not answer: no reply to sample {} after {} attempt(s) of {} ms (is "
        "the Basys-3 programmed with the flange bitstream, is this its UART port, is the baud "
        "rate {}?)",
        port_.device(), counts.samples, settings_.retries + 1, settings_.timeout_ms,
        settings_.baud));
  }

  // The reply with this SEQ if it comes within the timeout; replies with another SEQ are stray.
  std::optional<board::Reply> await_reply(std::uint8_t seq, std::chrono::milliseconds timeout,
                                          StreamCounts& counts) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (true) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
          deadline - std::chrono::steady_clock::now());
      if (left.count() <= 0) return std::nullopt;
      std::array<std::uint8_t, 64> buffer{};
      const std::size_t n = port_.read_some(buffer, left);
      for (std::size_t i = 0; i < n; ++i) {
        if (std::optional<board::Reply> reply = scanner_.push(buffer[i])) {
          if (reply->seq == seq) {
            counts.discarded_bytes = scanner_.discarded();
            return reply;
          }
          ++counts.stray_replies;
        }
      }
    }
  }

  SerialPort& port_;
  const StreamSettings& settings_;
  board::ReplyScanner scanner_;
};

void count_status(std::uint8_t status, StreamCounts& counts) {
  counts.link_errors += (status & board::kStatusLinkError) ? 1 : 0;
  counts.overruns += (status & board::kStatusOverrun) ? 1 : 0;
  counts.saturated += (status & board::kStatusSaturation) ? 1 : 0;
  counts.bypassed += (status & board::kStatusBypass) ? 1 : 0;
}

}  // namespace

StreamCounts stream_recording(const StreamSettings& settings) {
  const auto start = std::chrono::steady_clock::now();
  StreamCounts counts;
  // Voltage and temperature to clearance: the host's regression stage, as in `flange run`.
  std::function<double(double, double)> clearance_of = eq_3_14;
  if (!settings.calibration.empty()) {
    clearance_of = [calibration = load_calibration(settings.calibration)](double v, double t) {
      return calibration.estimate(v, t).clearance_mm;
    };
  }
  // The whole recording is checked before the board sees a sample, so a bad row cannot stop
  // a session half-way (a first pass, so memory stays flat).
  {
    RecordingReader check(settings.input);
    while (check.next()) {
    }
  }
  RecordingReader reader(settings.input);
  std::ofstream csv(settings.out, std::ios::binary);
  if (!csv) throw std::runtime_error("cannot write " + settings.out);
  SerialPort port(settings.port, settings.baud);
  port.discard_input();
  BoardLink link(port, settings);
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
    count_status(reply.status, counts);
    // The Butterworth designs have no leftover gain (1.0): the word is the clearance.
    const double filt_mm = scaling.unit_to_mm(reply.sample / scaling.full_scale());
    csv << fmt::format("{},{},{},{},{},{}\n", row->t_s, fixed6(raw_mm), word, reply.sample,
                       fixed6(filt_mm), reply.status);
    seq = static_cast<std::uint8_t>(seq + 1);
  }
  counts.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return counts;
}

std::string stream_summary_line(const StreamCounts& counts) {
  return fmt::format(
      "stream: {} samples in {:.2f} s, {} resent, {} stray replies, {} discarded bytes; board "
      "reported {} link errors, {} overruns, {} saturated, {} bypassed; {} inputs clipped",
      counts.samples, counts.seconds, counts.resent, counts.stray_replies, counts.discarded_bytes,
      counts.link_errors, counts.overruns, counts.saturated, counts.bypassed,
      counts.clipped_inputs);
}

}  // namespace flange::host
