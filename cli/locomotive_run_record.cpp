// SPDX-License-Identifier: MIT
#include "locomotive_run_record.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include "axle_clearance.h"
#include "locomotive_summary.h"

namespace flange::cli {
namespace {

// One wheel's trace past the filter's start-up, with its instants.
struct SettledTrace {
  std::vector<double> t_s;
  host::WheelSamples samples;
  double step_s = 0.0;  // between trace points
};

// The first instant past the filter's start-up (the recording's first instant + its transient).
double settled_from_s(const host::RunSummary& summary, const host::RunTrace& trace) {
  return trace.t_s.front() + static_cast<double>(summary.settle_samples) / summary.fs_hz;
}

SettledTrace settled_trace(const host::ChannelRun& channel) {
  const host::RunTrace& trace = channel.trace;
  SettledTrace settled;
  if (trace.t_s.empty() || channel.summary.fs_hz <= 0.0) return settled;
  const double from_s = settled_from_s(channel.summary, trace);
  settled.step_s = static_cast<double>(trace.stride) / channel.summary.fs_hz;
  for (std::size_t k = 0; k < trace.t_s.size(); ++k) {
    if (trace.t_s[k] < from_s) continue;
    settled.t_s.push_back(trace.t_s[k]);
    settled.samples.clearance_mm.push_back(trace.filt_mm[k]);
    settled.samples.temp_c.push_back(trace.temp_c[k]);
  }
  return settled;
}

void append_sample(host::WheelSamples& to, const SettledTrace& from, std::size_t k) {
  to.clearance_mm.push_back(from.samples.clearance_mm[k]);
  to.temp_c.push_back(from.samples.temp_c[k]);
}

// The samples of both wheels of an axle at the instants both have (within half a trace step):
// axle_clearance pairs them by position.
std::pair<host::WheelSamples, host::WheelSamples> common_instants(const SettledTrace& left,
                                                                  const SettledTrace& right) {
  const double tolerance_s = 0.5 * std::min(left.step_s, right.step_s);
  std::pair<host::WheelSamples, host::WheelSamples> pairs;
  std::size_t i = 0, j = 0;
  while (i < left.t_s.size() && j < right.t_s.size()) {
    if (left.t_s[i] < right.t_s[j] - tolerance_s) {
      ++i;
    } else if (right.t_s[j] < left.t_s[i] - tolerance_s) {
      ++j;
    } else {
      append_sample(pairs.first, left, i++);
      append_sample(pairs.second, right, j++);
    }
  }
  return pairs;
}

// Each channel's static clearance at reference conditions, by its index in run.channels.
std::vector<std::optional<double>> wheel_clearances(const host::LocomotiveRun& run,
                                                    const std::vector<SettledTrace>& settled) {
  std::map<int, std::array<std::optional<std::size_t>, 2>> axles;  // left, right
  for (std::size_t k = 0; k < run.channels.size(); ++k) {
    const host::ManifestChannel& channel = run.channels[k].channel;
    axles[channel.axle][channel.side == host::ManifestSide::kLeft ? 0 : 1] = k;
  }
  std::vector<std::optional<double>> clearance(run.channels.size());
  for (const auto& axle : axles) {
    const auto& [left, right] = axle.second;
    if (left && right) {
      const auto [left_samples, right_samples] = common_instants(settled[*left], settled[*right]);
      if (const auto both = host::axle_clearance(left_samples, right_samples)) {
        clearance[*left] = both->left_mm;
        clearance[*right] = both->right_mm;
      }
    } else {
      const std::size_t lone = left ? *left : *right;
      clearance[lone] = host::lone_wheel_clearance(settled[lone].samples);
    }
  }
  return clearance;
}

host::WheelRunResult wheel_result(const host::ChannelRun& channel, const SettledTrace& settled,
                                  std::optional<double> clearance_mm,
                                  std::optional<double> new_flange_gap_mm) {
  const host::RunSummary& summary = channel.summary;
  host::WheelRunResult wheel;
  wheel.axle = channel.channel.axle;
  wheel.side = host::manifest_side_name(channel.channel.side);
  wheel.channel = channel.channel.channel;
  wheel.clearance_mm = clearance_mm;
  if (clearance_mm && new_flange_gap_mm) wheel.wear_mm = *clearance_mm - *new_flange_gap_mm;
  const std::vector<double>& temps = settled.samples.temp_c;
  double temp_sum = 0.0;
  for (const double t : temps) temp_sum += t;
  wheel.temp_c = temps.empty() ? 0.0 : temp_sum / static_cast<double>(temps.size());
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

void add_reduced_trace(host::RunRecord& record, const host::RunSummary& summary,
                       const host::RunTrace& trace, int axle, const std::string& side) {
  if (trace.t_s.empty() || summary.fs_hz <= 0.0) return;
  const double from_s = settled_from_s(summary, trace);
  const double duration_s = trace.t_s.back() - trace.t_s.front();
  // The run's last instant closes its last kilometre rather than opening one of its own.
  const long last_km = std::max(0L, static_cast<long>(std::ceil(record.distance_km)) - 1);
  std::map<long, host::TracePoint> bins;
  for (std::size_t k = 0; k < trace.t_s.size(); ++k) {
    if (trace.t_s[k] < from_s || !std::isfinite(trace.filt_mm[k])) continue;
    const double fraction =
        duration_s > 0.0 ? (trace.t_s[k] - trace.t_s.front()) / duration_s : 0.0;
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

host::RunRecord locomotive_run_record(const host::LocomotiveRun& run, const std::string& locomotive,
                                      double distance_km, std::optional<double> new_flange_gap_mm) {
  host::RunRecord record;
  record.locomotive = locomotive;
  record.distance_km = distance_km;
  std::vector<SettledTrace> settled;
  for (const host::ChannelRun& channel : run.channels) settled.push_back(settled_trace(channel));
  const std::vector<std::optional<double>> clearances = wheel_clearances(run, settled);
  for (std::size_t k = 0; k < run.channels.size(); ++k) {
    const host::ChannelRun& channel = run.channels[k];
    const int axle = channel.channel.axle;
    const std::string side = host::manifest_side_name(channel.channel.side);
    record.sample_rate_hz = channel.summary.fs_hz;
    record.rows += channel.summary.rows_read;
    record.flagged_rows += channel.summary.rows_flagged;
    record.bad_rows += channel.summary.bad_rows;
    record.wheels.push_back(wheel_result(channel, settled[k], clearances[k], new_flange_gap_mm));
    for (const host::AlarmEvent& event : channel.summary.alarm_events) {
      record.alarms.push_back({axle, side, event.t_s, event.what});
    }
    add_reduced_trace(record, channel.summary, channel.trace, axle, side);
  }
  if (const std::optional<std::size_t> worst = host::worst_channel(run)) {
    record.final_alarm = run.channels[*worst].summary.final_alarm;
  }
  return record;
}

}  // namespace flange::cli
