// SPDX-License-Identifier: MIT
#include "locomotive_report.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <stdexcept>

#include "gnuplot_runner.h"
#include "locomotive_summary.h"
#include "report_format.h"
#include "run_report.h"

namespace flange::host {
namespace {

// Points per panel: about one per pixel of a 480-pixel-wide panel, so that twelve panels make
// an SVG of a few hundred kB.
constexpr std::size_t kPanelPoints = 500;

std::string channel_folder(int channel) { return fmt::format("channel_{:02d}", channel); }

// Time, filtered and reference clearance of one channel, thinned to kPanelPoints.
std::vector<std::vector<double>> panel_columns(const RunTrace& trace) {
  const std::size_t stride =
      std::max<std::size_t>(1, (trace.t_s.size() + kPanelPoints - 1) / kPanelPoints);
  std::vector<std::vector<double>> columns(3);
  for (std::size_t k = 0; k < trace.t_s.size(); k += stride) {
    columns[0].push_back(trace.t_s[k]);
    columns[1].push_back(trace.filt_mm[k]);
    columns[2].push_back(trace.reference_mm[k]);
  }
  return columns;
}

// The clearance range every panel shares, so that panels compare at a glance.
std::pair<double, double> shared_clearance_range(const LocomotiveRun& run, double critical_mm) {
  double low = std::numeric_limits<double>::infinity();
  double high = critical_mm;
  for (const ChannelRun& c : run.channels) {
    for (const std::vector<double>* v : {&c.trace.filt_mm, &c.trace.reference_mm}) {
      for (const double x : *v) {
        if (std::isnan(x)) continue;
        low = std::min(low, x);
        high = std::max(high, x);
      }
    }
  }
  if (!std::isfinite(low)) low = 0.0;
  return {std::floor(low - 0.5), std::ceil(high + 0.5)};
}

// The time axis every panel shares: to the latest sample of any channel.
double last_time_s(const LocomotiveRun& run) {
  double last = 0.0;
  for (const ChannelRun& c : run.channels) {
    if (!c.trace.t_s.empty()) last = std::max(last, c.trace.t_s.back());
  }
  return last > 0.0 ? last : 1.0;
}

const ChannelRun* channel_at(const LocomotiveRun& run, int axle, ManifestSide side) {
  for (const ChannelRun& c : run.channels) {
    if (c.channel.axle == axle && c.channel.side == side) return &c;
  }
  return nullptr;
}

// One panel of the small multiples: a wheel's filtered clearance and reference, or an empty
// panel where the wheel has no channel.
std::string panel_script(const ChannelRun* c, const std::string& wheel, bool worst,
                         double warning_mm, double critical_mm) {
  if (c == nullptr) return fmt::format("set title '{}: no channel'\nplot NaN notitle\n", wheel);
  const std::string block = fmt::format("ch{}", c->channel.channel);
  std::string script = coeffs::gnuplot_data_block(block, panel_columns(c->trace));
  script +=
      fmt::format("set title 'channel {}: {}{}' tc rgb '{}'\n", c->channel.channel,
                  wheel_label(c->channel), worst ? " (worst)" : "", worst ? "#d62728" : "#000000");
  script += "plot ";
  if (c->summary.has_reference) {
    script += fmt::format("${} using 1:3 with lines lc rgb '#aaaaaa', ", block);
  }
  script += fmt::format(
      "${} using 1:2 with lines lw 1.5 lc rgb '#1f77b4', {} with lines dt 2 lc rgb '#ff7f0e', "
      "{} with lines dt 2 lc rgb '#d62728'\n",
      block, warning_mm, critical_mm);
  return script;
}

void plot_small_multiples(const std::filesystem::path& dir, const LocomotiveRun& run,
                          std::optional<std::size_t> worst) {
  const ThresholdConfig& t = run.channels.front().options.thresholds;
  const double critical_mm = t.flange_nominal_mm + t.sensor_gap_mm - t.critical_flange_mm;
  int axles = 1;
  for (const ChannelRun& c : run.channels) axles = std::max(axles, c.channel.axle);
  const std::filesystem::path svg = dir / "clearance.svg";
  std::string script = coeffs::gnuplot_svg_terminal(svg, 1000, 70 + 170 * axles, false);
  const auto [low, high] = shared_clearance_range(run, critical_mm);
  script += fmt::format(
      "set multiplot layout {},2 title 'clearance by wheel (mm), axles down, left and right "
      "across: filtered (blue), reference (grey), warning and critical (dashed)'\n"
      "set xrange [0:{}]\nset yrange [{}:{}]\nset ylabel 'clearance (mm)'\nunset key\n",
      axles, last_time_s(run), low, high);
  for (int axle = 1; axle <= axles; ++axle) {
    if (axle == axles) script += "set xlabel 'time (s)'\n";  // on the bottom row only
    for (const ManifestSide side : {ManifestSide::kLeft, ManifestSide::kRight}) {
      const ChannelRun* c = channel_at(run, axle, side);
      const bool is_worst = c != nullptr && worst && &run.channels[*worst] == c;
      const std::string wheel = fmt::format("axle {} {}", axle, manifest_side_name(side));
      script += panel_script(c, wheel, is_worst, t.warning_clearance_mm, critical_mm);
    }
  }
  script += "unset multiplot\n";
  coeffs::run_gnuplot(script, svg.string());
}

std::string table_cell(const std::optional<double>& value, int decimals) {
  return value ? fmt::format("{:.{}f}", *value, decimals) : "-";
}

void write_table(std::ofstream& html, const LocomotiveRun& run, std::optional<std::size_t> worst) {
  html << "<table><tr><th>ch</th><th>wheel</th><th>rows</th><th>flagged</th><th>final (mm)</th>"
          "<th>min (mm)</th><th>max (mm)</th><th>final alarm</th><th>warning from (s)</th>"
          "<th>critical from (s)</th><th>wear steps</th><th>report</th></tr>\n";
  for (std::size_t k = 0; k < run.channels.size(); ++k) {
    const ChannelRun& c = run.channels[k];
    const RunSummary& s = c.summary;
    const AlarmDigest alarms = digest_alarms(s);
    const bool settled = s.filtered.has_settled_rows();
    html << (worst && *worst == k ? "<tr class='worst'>" : "<tr>");
    html << fmt::format(
        "<td>{}</td><td>{}{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td>"
        "<td>{}</td><td>{}</td><td>{}</td><td>{}</td><td><a href='{}/index.html'>{}</a></td>"
        "</tr>\n",
        c.channel.channel, wheel_label(c.channel), worst && *worst == k ? " (worst)" : "",
        s.rows_read, s.rows_flagged, table_cell(s.filtered.last_mm, 3),
        settled ? fmt::format("{:.3f}", s.filtered.min_mm) : "-",
        settled ? fmt::format("{:.3f}", s.filtered.max_mm) : "-", s.final_alarm,
        table_cell(alarms.first_warning_s, 2), table_cell(alarms.first_critical_s, 2),
        alarms.wear_steps, channel_folder(c.channel.channel), channel_folder(c.channel.channel));
  }
  html << "</table>\n";
}

}  // namespace

void write_locomotive_report(const std::filesystem::path& dir, const LocomotiveRun& run) {
  std::filesystem::create_directories(dir);
  const std::optional<std::size_t> worst = worst_channel(run);
  plot_small_multiples(dir, run, worst);
  for (const ChannelRun& c : run.channels) {
    write_run_report(dir / channel_folder(c.channel.channel), c.options, c.summary, c.trace);
  }
  std::ofstream html(dir / "index.html", std::ios::binary);
  if (!html) throw std::runtime_error("cannot write " + (dir / "index.html").string());
  html << "<!DOCTYPE html>\n<html><head><meta charset='utf-8'><title>flange run: "
       << coeffs::html_escape(run.manifest.path) << "</title>\n<style>body{font-family:sans-serif;"
       << "max-width:1050px;margin:1em auto}pre{background:#f4f4f4;padding:.8em}"
       << "img{max-width:100%}table{border-collapse:collapse}td,th{padding:.2em .5em;"
       << "border-bottom:1px solid #ddd;text-align:right}tr.worst{background:#fde0dd}"
       << "</style></head><body>\n";
  html << "<h1>flange run: a locomotive</h1>\n<p>" << coeffs::html_escape(run.manifest.path) << ": "
       << run.channels.size() << " channel(s), each run alone through "
       << coeffs::html_escape(run.channels.front().options.coeffs) << " (engine "
       << run.channels.front().summary.engine << "). min and max leave out the filter's start-up ("
       << run.channels.front().summary.settle_samples
       << " samples). The worst wheel: the highest alarm raised, reached first; without alarms, "
          "the largest filtered clearance.</p>\n";
  write_table(html, run, worst);
  html << "<h2>Filtered clearance by wheel</h2><p>Every panel on one clearance scale; dashed: "
          "the warning and critical clearances. In a curve the wheelset shifts towards the "
          "outer rail: the outer wheel's clearance closes and the inner one's opens by as "
          "much.</p>"
          "<img src='clearance.svg'>\n";
  html << "<h2>Each channel</h2>\n";
  for (const ChannelRun& c : run.channels) {
    html << "<details><summary>channel " << c.channel.channel << ": " << wheel_label(c.channel)
         << "</summary><pre>" << coeffs::html_escape(run_summary_text(c.options, c.summary))
         << "</pre></details>\n";
  }
  html << "</body></html>\n";
}

}  // namespace flange::host
