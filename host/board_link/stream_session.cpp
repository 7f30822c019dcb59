// SPDX-License-Identifier: MIT
#include "stream_session.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>

#include "calibration.h"
#include "fixed_decimals.h"
#include "input_error.h"
#include "recording_csv.h"
#include "sample_scaling.h"
#include "serial_port.h"

namespace flange::host {
namespace {

using ClearanceOf = std::function<double(double voltage_v, double temp_c)>;

// One channel during a session: its recording, its regression, its output.
struct ChannelRun {
  int channel = 0;
  ClearanceOf clearance_of;
  std::unique_ptr<RecordingReader> reader;
  std::optional<RecordingRow> row;  // the next row to send
  std::ofstream csv;
};

// Voltage and temperature to clearance: the host's regression stage, as in `flange run`; each
// calibration file is read once.
ClearanceOf clearance_function(const std::string& calibration,
                               std::map<std::string, ClearanceOf>& loaded) {
  if (calibration.empty()) return eq_3_14;
  auto found = loaded.find(calibration);
  if (found == loaded.end()) {
    found = loaded
                .emplace(calibration,
                         [model = load_calibration(calibration)](double v, double t) {
                           return model.estimate(v, t).clearance_mm;
                         })
                .first;
  }
  return found->second;
}

std::string source_of(const ChannelStreamSettings& settings) {
  if (!settings.source.empty()) return settings.source;
  return settings.channels.size() == 1 ? settings.channels[0].input : "the channel list";
}

// Everything that can be wrong with the input is found before the port is opened: the channel
// list, every row of every recording, the coefficient set.
std::vector<int> channel_numbers(const ChannelStreamSettings& settings) {
  std::vector<int> numbers;
  numbers.reserve(settings.channels.size());
  for (const ChannelFiles& files : settings.channels) numbers.push_back(files.channel);
  return numbers;
}

// Everything that can be wrong with the input is found before the port is opened: the channel
// list, every row of every recording, the coefficient set.
std::optional<ReplyChecker> check_input(const ChannelStreamSettings& settings) {
  const std::vector<int> numbers = channel_numbers(settings);
  check_channel_numbers(numbers, nullptr, source_of(settings));
  // A first pass, so that a bad row cannot stop a session half-way and memory stays flat.
  for (const ChannelFiles& files : settings.channels) {
    RecordingReader check(files.input);
    while (check.next()) {
    }
  }
  std::optional<ReplyChecker> checker;
  if (!settings.coeffs.empty()) {
    try {
      checker.emplace(model::load_core_config(settings.coeffs));
    } catch (const model::FilterJsonError& error) {
      throw InputError(error.what());
    }
  }
  if (checker) check_channel_numbers(numbers, &*checker, source_of(settings));
  return checker;
}

std::vector<ChannelRun> open_channels(const ChannelStreamSettings& settings) {
  std::map<std::string, ClearanceOf> loaded;
  std::vector<ChannelRun> runs(settings.channels.size());
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const ChannelFiles& files = settings.channels[i];
    ChannelRun& run = runs[i];
    run.channel = files.channel;
    run.clearance_of = clearance_function(
        files.calibration.empty() ? settings.calibration : files.calibration, loaded);
    run.reader = std::make_unique<RecordingReader>(files.input);
    run.row = run.reader->next();
    run.csv.open(files.out, std::ios::binary);
    if (!run.csv) throw std::runtime_error("cannot write " + files.out);
    run.csv << "t_s,clearance_raw_mm,word_in,word_out,clearance_filt_mm,status\n";
  }
  return runs;
}

// The channel whose next row is the earliest (the first listed on a tie); nullptr when done.
ChannelRun* earliest(std::vector<ChannelRun>& runs) {
  ChannelRun* next = nullptr;
  for (ChannelRun& run : runs) {
    if (run.row && (!next || run.row->t_s < next->row->t_s)) next = &run;
  }
  return next;
}

}  // namespace

StreamCounts stream_channel_recordings(const ChannelStreamSettings& settings) {
  const auto start = std::chrono::steady_clock::now();
  std::optional<ReplyChecker> checker = check_input(settings);
  std::vector<ChannelRun> runs = open_channels(settings);
  const std::vector<int> numbers = channel_numbers(settings);

  SerialPort port(settings.port, settings.link.baud);
  const std::string latency = port.request_low_latency();
  if (settings.on_port_setup) settings.on_port_setup(latency);
  port.discard_input();
  BoardLink link(port, settings.link);
  // A fresh filter on every channel, as `flange run` starts with: the outputs equal the model's.
  ChannelSession session(link, numbers, checker ? &*checker : nullptr, source_of(settings));
  const SampleScaling scaling;
  std::uint64_t clipped_inputs = 0;
  while (ChannelRun* run = earliest(runs)) {
    const RecordingRow& row = *run->row;
    const double raw_mm = run->clearance_of(row.voltage_v, row.temp_c);
    bool clipped = false;
    const auto word = static_cast<std::int16_t>(scaling.to_word(raw_mm, clipped));
    clipped_inputs += clipped ? 1 : 0;
    // The row's reply comes later (a window of requests is in flight), in the order sent.
    session.send(run->channel, word,
                 [&scaling, csv = &run->csv, t_s = row.t_s, raw_mm, word](const board::Reply& r) {
                   // The Butterworth designs have no leftover gain (1.0): the word is the
                   // clearance.
                   const double filt_mm = scaling.unit_to_mm(r.sample / scaling.full_scale());
                   *csv << fmt::format("{},{},{},{},{},{}\n", t_s, fixed6(raw_mm), word, r.sample,
                                       fixed6(filt_mm), r.status);
                 });
    run->row = run->reader->next();
  }
  session.finish();
  StreamCounts counts = session.counts();
  counts.clipped_inputs = clipped_inputs;
  counts.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return counts;
}

StreamCounts stream_recording(const StreamSettings& settings) {
  ChannelStreamSettings multi;
  multi.port = settings.port;
  multi.channels = {{0, settings.input, settings.out, ""}};
  multi.calibration = settings.calibration;
  multi.link = {settings.baud, settings.timeout_ms, settings.retries, settings.window};
  multi.on_port_setup = settings.on_port_setup;
  return stream_channel_recordings(multi);
}

}  // namespace flange::host
