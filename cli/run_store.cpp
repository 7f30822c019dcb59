// SPDX-License-Identifier: MIT
#include "run_store.h"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "content_sha256.h"
#include "locomotive_summary.h"
#include "utc_time.h"

namespace flange::cli {

namespace {

std::string started_at(const RunStoreOptions& options) {
  if (options.started_at)
    return format_utc_time(parse_utc_time(*options.started_at, "--started-at"));
  const auto now = std::chrono::system_clock::now().time_since_epoch();
  return format_utc_time(std::chrono::duration<double>(now).count());
}

std::string file_text(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

// The stored calibration whose model.json is the file given (calibrations are kept as written).
std::optional<std::int64_t> stored_calibration(host::Store& store, const std::string& path) {
  std::string text = file_text(path);
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
  std::optional<std::int64_t> found;
  for (const auto& [id, calibration] : store.calibrations()) {
    if (calibration.model_json == text) found = id;  // the latest of equal refits
  }
  return found;
}

// The per-kilometre means of one channel's trace past the start-up (see run_store.h).
void add_reduced_trace(host::RunRecord& record, const host::RunSummary& summary,
                       const host::RunTrace& trace, int axle, const std::string& side) {
  if (trace.t_s.empty() || summary.fs_hz <= 0.0) return;
  const double settle_s = static_cast<double>(summary.settle_samples) / summary.fs_hz;
  const double duration_s = trace.t_s.back() - trace.t_s.front();
  std::map<long, host::TracePoint> bins;
  for (std::size_t k = 0; k < trace.t_s.size(); ++k) {
    if (trace.t_s[k] < settle_s || !std::isfinite(trace.filt_mm[k])) continue;
    const double fraction =
        duration_s > 0.0 ? (trace.t_s[k] - trace.t_s.front()) / duration_s : 0.0;
    // The run's last instant closes its last kilometre rather than opening one of its own.
    const long last_km = std::max(0L, static_cast<long>(std::ceil(record.distance_km)) - 1);
    const long km = std::min(last_km, static_cast<long>(std::floor(fraction * record.distance_km)));
    host::TracePoint& point = bins[km];
    point.axle = axle;
    point.side = side;
    point.km = static_cast<double>(km);
    point.clearance_mm += trace.filt_mm[k];
    point.temp_c += trace.temp_c[k];
    point.samples += trace.stride;  // each trace point stands for `stride` rows
  }
  for (auto& [km, point] : bins) {
    const double points = static_cast<double>(point.samples / trace.stride);
    point.clearance_mm /= points;
    point.temp_c /= points;
    record.trace.push_back(point);
  }
}

nlohmann::ordered_json summary_figures(const host::RunSummary& summary) {
  nlohmann::ordered_json json = {{"rows", summary.rows_read},
                                 {"rows_flagged", summary.rows_flagged},
                                 {"bad_rows", summary.bad_rows},
                                 {"outside_calibration", summary.outside_calibration},
                                 {"clipped_samples", summary.clipped_samples},
                                 {"saturated_outputs", summary.saturated_outputs},
                                 {"rtl_mismatches", summary.rtl_mismatches},
                                 {"final_alarm", summary.final_alarm}};
  if (summary.has_reference) {
    json["mae_before_mm"] = summary.before.mae();
    json["mae_after_mm"] = summary.after.mae();
  }
  return json;
}

host::RunRecord run_record(host::Store& store, const RunStoreOptions& options,
                           const host::RunOptions& run, const std::string& source,
                           const std::string& source_sha256, const std::string& label) {
  host::SessionRecord session;
  session.kind = host::SessionKind::kService;
  session.label = label;
  session.started_at = started_at(options);
  session.source_file = source;
  session.source_sha256 = source_sha256;
  host::RunRecord record;
  record.started_at = session.started_at;
  record.distance_km = options.distance_km;
  record.odometer_km = options.odometer_km;
  record.coefficient_set = run.coeffs;
  record.coefficient_sha256 = host::file_sha256(run.coeffs);
  record.calibration_id = stored_calibration(store, run.calibration);
  record.engine = run.engine;
  record.session = session;
  return record;
}

void add_counts(host::RunRecord& record, const host::RunSummary& summary) {
  record.sample_rate_hz = summary.fs_hz;
  record.rows += summary.rows_read;
  record.flagged_rows += summary.rows_flagged;
  record.bad_rows += summary.bad_rows;
}

host::WheelRunResult wheel_result(const host::ChannelRun& channel,
                                  const std::vector<host::TracePoint>& trace) {
  const host::RunSummary& summary = channel.summary;
  host::WheelRunResult wheel;
  wheel.axle = channel.channel.axle;
  wheel.side = host::manifest_side_name(channel.channel.side);
  wheel.channel = channel.channel.channel;
  double clearance = 0.0, temp = 0.0, samples = 0.0;
  for (const host::TracePoint& point : trace) {
    if (point.axle != wheel.axle || point.side != wheel.side) continue;
    clearance += point.clearance_mm * static_cast<double>(point.samples);
    temp += point.temp_c * static_cast<double>(point.samples);
    samples += static_cast<double>(point.samples);
  }
  if (samples > 0.0) wheel.clearance_mm = clearance / samples;  // mean settled clearance
  wheel.temp_c = samples > 0.0 ? temp / samples : 0.0;
  wheel.samples = summary.rows_read;
  wheel.flagged_samples = summary.rows_flagged;
  wheel.final_alarm = summary.final_alarm;
  if (summary.has_reference) {
    wheel.mae_before_mm = summary.before.mae();
    wheel.mae_after_mm = summary.after.mae();
  }
  return wheel;
}

}  // namespace

std::int64_t store_recording_run(host::Store& store, const RunStoreOptions& options,
                                 const host::RunOptions& run, const host::RunSummary& summary,
                                 const host::RunTrace& trace) {
  host::RunRecord record = run_record(store, options, run, run.input, host::file_sha256(run.input),
                                      std::filesystem::path(run.input).stem().string());
  add_counts(record, summary);
  record.final_alarm = summary.final_alarm;
  for (const host::AlarmEvent& event : summary.alarm_events) {
    record.alarms.push_back({0, "", event.t_s, event.what});
  }
  add_reduced_trace(record, summary, trace, 0, "");
  record.summary_json = summary_figures(summary).dump();
  return store.record_run(record);
}

std::int64_t store_locomotive_run(host::Store& store, const RunStoreOptions& options,
                                  const host::LocomotiveRun& run) {
  const std::filesystem::path manifest(run.manifest.path);
  const std::string locomotive =
      !options.locomotive.empty()
          ? options.locomotive
          : std::filesystem::absolute(manifest).parent_path().filename().string();
  // The session's hash covers the manifest and every channel's recording.
  std::string hashes = host::file_sha256(run.manifest.path) + "\n";
  for (const host::ChannelRun& channel : run.channels) {
    hashes += host::file_sha256(channel.options.input) + "\n";
  }
  host::RunRecord record = run_record(store, options, run.channels.at(0).options, run.manifest.path,
                                      host::text_sha256(hashes), locomotive);
  record.locomotive = locomotive;
  nlohmann::ordered_json channels = nlohmann::ordered_json::array();
  for (const host::ChannelRun& channel : run.channels) {
    const int axle = channel.channel.axle;
    const std::string side = host::manifest_side_name(channel.channel.side);
    add_counts(record, channel.summary);
    add_reduced_trace(record, channel.summary, channel.trace, axle, side);
    record.wheels.push_back(wheel_result(channel, record.trace));
    for (const host::AlarmEvent& event : channel.summary.alarm_events) {
      record.alarms.push_back({axle, side, event.t_s, event.what});
    }
    channels.push_back(summary_figures(channel.summary));
    channels.back()["channel"] = channel.channel.channel;
  }
  if (const std::optional<std::size_t> worst = host::worst_channel(run)) {
    record.final_alarm = run.channels[*worst].summary.final_alarm;
  }
  record.summary_json = nlohmann::ordered_json{{"channels", channels}}.dump();
  return store.record_run(record);
}

}  // namespace flange::cli
