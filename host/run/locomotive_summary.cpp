// SPDX-License-Identifier: MIT
#include "locomotive_summary.h"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <tuple>

namespace flange::host {
namespace {

using nlohmann::ordered_json;

std::string optional_number(const std::optional<double>& value, int decimals) {
  return value ? fmt::format("{:.{}f}", *value, decimals) : "-";
}

// Sort key of a channel: larger is worse.
std::tuple<int, double, double> badness(const ChannelRun& channel) {
  const AlarmDigest alarms = digest_alarms(channel.summary);
  const std::optional<double> reached =
      alarms.highest == AlarmLevel::kCritical ? alarms.first_critical_s : alarms.first_warning_s;
  const double max_mm = channel.summary.filtered.has_settled_rows()
                            ? channel.summary.filtered.max_mm
                            : -std::numeric_limits<double>::infinity();
  // Reached earlier is worse, so the time enters negated.
  return {static_cast<int>(alarms.highest), reached ? -*reached : 0.0, max_mm};
}

ordered_json errors_json(const ErrorStats& stats) {
  return {{"mae_mm", stats.mae()},
          {"rmse_mm", stats.rmse()},
          {"max_mm", stats.max_abs},
          {"samples", stats.n}};
}

ordered_json channel_json(const ChannelRun& c) {
  const RunSummary& s = c.summary;
  const AlarmDigest alarms = digest_alarms(s);
  ordered_json entry{{"channel", c.channel.channel},
                     {"axle", c.channel.axle},
                     {"side", manifest_side_name(c.channel.side)},
                     {"input", c.options.input},
                     {"output", c.options.out_csv ? ordered_json(*c.options.out_csv) : nullptr},
                     {"rows_read", s.rows_read},
                     {"rows_flagged", s.rows_flagged},
                     {"bad_rows", s.bad_rows},
                     {"outside_calibration", s.outside_calibration},
                     {"clipped_samples", s.clipped_samples},
                     {"saturated_outputs", s.saturated_outputs},
                     {"rtl_mismatches", s.rtl_mismatches}};
  entry["final_filtered_mm"] = s.filtered.last_mm ? ordered_json(*s.filtered.last_mm) : nullptr;
  entry["min_filtered_mm"] =
      s.filtered.has_settled_rows() ? ordered_json(s.filtered.min_mm) : nullptr;
  entry["max_filtered_mm"] =
      s.filtered.has_settled_rows() ? ordered_json(s.filtered.max_mm) : nullptr;
  entry["settle_samples"] = s.settle_samples;
  entry["final_alarm"] = s.final_alarm;
  entry["highest_alarm"] = alarm_name(alarms.highest);
  entry["first_warning_s"] =
      alarms.first_warning_s ? ordered_json(*alarms.first_warning_s) : nullptr;
  entry["first_critical_s"] =
      alarms.first_critical_s ? ordered_json(*alarms.first_critical_s) : nullptr;
  entry["alarm_events"] = ordered_json::array();
  for (const AlarmEvent& event : s.alarm_events) {
    entry["alarm_events"].push_back({{"t_s", event.t_s}, {"what", event.what}});
  }
  if (s.has_reference) {
    entry["error_before_filtering"] = errors_json(s.before);
    entry["error_after_filtering"] = errors_json(s.after);
  }
  return entry;
}

}  // namespace

AlarmDigest digest_alarms(const RunSummary& summary) {
  AlarmDigest digest;
  for (const AlarmEvent& event : summary.alarm_events) {
    if (event.what == alarm_name(AlarmLevel::kWarning) && !digest.first_warning_s) {
      digest.first_warning_s = event.t_s;
      digest.highest = std::max(digest.highest, AlarmLevel::kWarning);
    } else if (event.what == alarm_name(AlarmLevel::kCritical) && !digest.first_critical_s) {
      digest.first_critical_s = event.t_s;
      digest.highest = AlarmLevel::kCritical;
    } else if (event.what.rfind("wear_step", 0) == 0) {
      ++digest.wear_steps;
    }
  }
  return digest;
}

std::optional<std::size_t> worst_channel(const LocomotiveRun& run) {
  std::optional<std::size_t> worst;
  for (std::size_t k = 0; k < run.channels.size(); ++k) {
    if (!run.channels[k].summary.filtered.has_settled_rows()) continue;
    if (!worst || badness(run.channels[k]) > badness(run.channels[*worst])) worst = k;
  }
  return worst;
}

std::string locomotive_table_text(const LocomotiveRun& run) {
  std::ostringstream text;
  const RunSummary& first = run.channels.front().summary;
  text << fmt::format("run: {}: {} channel(s) through {} (engine {}, fs {:.6g} Hz)\n",
                      run.manifest.path, run.channels.size(), run.channels.front().options.coeffs,
                      first.engine, first.fs_hz);
  text << fmt::format("  {:>2}  {:<12} {:>9} {:>7} {:>8} {:>7} {:>7}  {:<8} {:>9} {:>10} {:>10}\n",
                      "ch", "wheel", "rows", "flagged", "final_mm", "min_mm", "max_mm", "alarm",
                      "warning_s", "critical_s", "wear_steps");
  for (const ChannelRun& c : run.channels) {
    const RunSummary& s = c.summary;
    const AlarmDigest alarms = digest_alarms(s);
    const bool settled = s.filtered.has_settled_rows();
    text << fmt::format(
        "  {:>2}  {:<12} {:>9} {:>7} {:>8} {:>7} {:>7}  {:<8} {:>9} {:>10} {:>10}\n",
        c.channel.channel, wheel_label(c.channel), s.rows_read, s.rows_flagged,
        optional_number(s.filtered.last_mm, 3),
        settled ? fmt::format("{:.3f}", s.filtered.min_mm) : "-",
        settled ? fmt::format("{:.3f}", s.filtered.max_mm) : "-", s.final_alarm,
        optional_number(alarms.first_warning_s, 2), optional_number(alarms.first_critical_s, 2),
        alarms.wear_steps);
    for (const std::string& message : s.bad_row_messages) text << "  bad row: " << message << "\n";
    if (s.rtl_mismatches > 0) {
      text << fmt::format("  channel {}: rtl disagreed with the model {} times\n",
                          c.channel.channel, s.rtl_mismatches);
    }
  }
  text << fmt::format(
      "  min_mm and max_mm leave out the first {} samples (the filter's start-up)\n",
      first.settle_samples);
  if (first.engine == "rtl") {
    std::uint64_t mismatches = 0;
    for (const ChannelRun& c : run.channels) mismatches += c.summary.rtl_mismatches;
    text << fmt::format("  rtl checked against the model on every channel: {} mismatches\n",
                        mismatches);
  }
  if (const std::optional<std::size_t> worst = worst_channel(run)) {
    const ChannelRun& c = run.channels[*worst];
    const AlarmDigest alarms = digest_alarms(c.summary);
    const std::string why =
        alarms.highest == AlarmLevel::kCritical
            ? fmt::format("critical from t = {:.2f} s", *alarms.first_critical_s)
        : alarms.highest == AlarmLevel::kWarning
            ? fmt::format("warning from t = {:.2f} s", *alarms.first_warning_s)
            : "no alarm; the largest filtered clearance";
    text << fmt::format("  worst wheel: channel {} ({}): {}, up to {:.3f} mm\n", c.channel.channel,
                        wheel_label(c.channel), why, c.summary.filtered.max_mm);
  }
  return text.str();
}

void write_locomotive_summary_json(const std::filesystem::path& path, const LocomotiveRun& run,
                                   const std::string& generated_by) {
  const ChannelRun& first = run.channels.front();
  ordered_json document{{"generated_by", generated_by},
                        {"manifest", run.manifest.path},
                        {"calibration", first.options.calibration},
                        {"coeffs", first.options.coeffs},
                        {"engine", first.summary.engine},
                        {"fs_hz", first.summary.fs_hz}};
  const std::optional<std::size_t> worst = worst_channel(run);
  document["worst_channel"] =
      worst ? ordered_json(run.channels[*worst].channel.channel) : ordered_json(nullptr);
  document["channels"] = ordered_json::array();
  for (const ChannelRun& c : run.channels) document["channels"].push_back(channel_json(c));
  std::ofstream file(path, std::ios::binary);
  file << document.dump(2) << "\n";
  file.close();
  if (!file) throw std::runtime_error("cannot write " + path.string());
}

}  // namespace flange::host
