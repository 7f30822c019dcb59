// SPDX-License-Identifier: MIT
#include "run_store.h"

#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "content_sha256.h"
#include "locomotive_run_record.h"
#include "utc_time.h"
#include "wheel_wear_reference.h"

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

// When and how the run ran, and its service session.
void describe_run(host::RunRecord& record, host::Store& store, const RunStoreOptions& options,
                  const host::RunOptions& run, const std::string& source,
                  const std::string& source_sha256, const std::string& label) {
  host::SessionRecord session;
  session.kind = host::SessionKind::kService;
  session.label = label;
  session.started_at = started_at(options);
  session.source_file = source;
  session.source_sha256 = source_sha256;
  record.started_at = session.started_at;
  record.odometer_km = options.odometer_km;
  record.coefficient_set = run.coeffs;
  record.coefficient_sha256 = host::file_sha256(run.coeffs);
  record.calibration_id = stored_calibration(store, run.calibration);
  record.engine = run.engine;
  record.session = session;
}

void add_counts(host::RunRecord& record, const host::RunSummary& summary) {
  record.sample_rate_hz = summary.fs_hz;
  record.rows += summary.rows_read;
  record.flagged_rows += summary.rows_flagged;
  record.bad_rows += summary.bad_rows;
}

}  // namespace

std::int64_t store_recording_run(host::Store& store, const RunStoreOptions& options,
                                 const host::RunOptions& run, const host::RunSummary& summary,
                                 const host::RunTrace& trace) {
  host::RunRecord record;
  record.distance_km = options.distance_km;
  describe_run(record, store, options, run, run.input, host::file_sha256(run.input),
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
  // Each wheel's clearance at reference conditions, and its wear against the reference the
  // depot's records give (wheel_wear_reference.h).
  host::RunRecord record = locomotive_run_record(run, locomotive, options.distance_km);
  const host::RunOptions& first = run.channels.at(0).options;
  describe_run(record, store, options, first, run.manifest.path, host::text_sha256(hashes),
               locomotive);
  record.odometer_km = continuous_odometer(store, record, options.odometer_km);
  fill_wheel_wear(store, record,
                  options.new_flange_clearance_mm.value_or(first.thresholds.sensor_gap_mm));
  nlohmann::ordered_json channels = nlohmann::ordered_json::array();
  for (const host::ChannelRun& channel : run.channels) {
    channels.push_back(summary_figures(channel.summary));
    channels.back()["channel"] = channel.channel.channel;
  }
  record.summary_json = nlohmann::ordered_json{{"channels", channels}}.dump();
  return store.record_run(record);
}

}  // namespace flange::cli
