// SPDX-License-Identifier: MIT
#include "wear_report.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <stdexcept>

#include "gnuplot_runner.h"
#include "report_format.h"
#include "wear_outputs.h"

namespace flange::host {
namespace {

using Panels = std::map<std::pair<int, std::string>, const WheelWear*>;

// Each run's wear and, per flange, the fitted wear: the history fit's broken line at every run
// (history_mean_rate.h), or the straight line's two ends; NaN between flanges.
std::string panel_data(const WheelWear& w, const std::string& block, double gap_mm) {
  std::vector<std::vector<double>> points(2);
  for (const WearObservation& run : w.runs) {
    points[0].push_back(run.odometer_km);
    points[1].push_back(run.clearance_mm - gap_mm);
  }
  std::string script = coeffs::gnuplot_data_block(block, points);
  std::vector<std::vector<double>> line(2);
  for (std::size_t k = 0; w.fit && k < w.runs.size(); ++k) {
    const bool first = k == 0 || w.segment[k] != w.segment[k - 1];
    const bool last = k + 1 == w.runs.size() || w.segment[k + 1] != w.segment[k];
    if (!first && !last && !w.history_mean) continue;
    if (first && k > 0) {
      line[0].push_back(w.runs[k].odometer_km);
      line[1].push_back(std::numeric_limits<double>::quiet_NaN());
    }
    line[0].push_back(w.runs[k].odometer_km);
    line[1].push_back((w.history_mean ? history_fit_at(*w.history_mean, k)
                                      : wear_line_at(*w.fit, w.segment[k], w.runs[k].odometer_km)) -
                      gap_mm);
  }
  return script + coeffs::gnuplot_data_block(block + "_fit", line);
}

std::string panel_script(const WheelWear* w, const std::string& label, int index,
                         const FleetWear& fleet) {
  if (w == nullptr) return fmt::format("set title '{}: no sensor'\nplot NaN notitle\n", label);
  const double gap = fleet.thresholds.sensor_gap_mm;
  const std::string block = fmt::format("w{}", index);
  const bool fault = w->status == "sensor fault" || w->status == "missed reprofiling";
  std::string script = panel_data(*w, block, gap);
  script +=
      fmt::format("set title '{}: {:.3f} mm/1000 km{}' tc rgb '{}'\n", label, w->rate_mm_per_1000km,
                  fault ? " (" + w->status + ")" : "", fault ? "#d62728" : "#000000");
  // A wheel with too few runs for a line has no fitted block to draw.
  const std::string line =
      w->fit ? fmt::format(", ${}_fit using 1:2 with lines lw 2 lc rgb '#000000'", block) : "";
  script += fmt::format(
      "plot ${} using 1:2 with points pt 7 ps 0.4 lc rgb '#1f77b4'{}, {} with lines dt 2 lc rgb "
      "'#ff7f0e', {} with lines dt 2 lc rgb '#d62728'\n",
      block, line, fleet.warning_clearance_mm - gap, fleet.critical_clearance_mm - gap);
  return script;
}

void plot_locomotive(const std::filesystem::path& svg, const std::string& locomotive,
                     const Panels& panels, const FleetWear& fleet) {
  int axles = 1;
  for (const auto& [key, wheel] : panels) axles = std::max(axles, key.first);
  std::string script = coeffs::gnuplot_svg_terminal(svg, 1000, 70 + 170 * axles, false);
  std::string name = locomotive;  // a gnuplot single-quoted string doubles its quotes
  for (std::size_t at = name.find('\''); at != std::string::npos; at = name.find('\'', at + 2)) {
    name.insert(at, 1, '\'');
  }
  script += fmt::format(
      "set multiplot layout {},2 title '{}: flange wear (mm) against odometer (km), axles down, "
      "left and right across: each run (dots), fitted wear per flange, warning and critical "
      "(dashed)'\nset yrange [-0.5:{}]\nunset key\nset ylabel 'wear (mm)'\n",
      axles, name, fleet.critical_clearance_mm - fleet.thresholds.sensor_gap_mm + 0.5);
  int index = 0;
  for (int axle = 1; axle <= axles; ++axle) {
    if (axle == axles) script += "set xlabel 'odometer (km)'\n";
    for (const std::string side : {"left", "right"}) {
      const auto at = panels.find({axle, side});
      script += panel_script(at == panels.end() ? nullptr : at->second,
                             fmt::format("axle {} {}", axle, side), index++, fleet);
    }
  }
  coeffs::run_gnuplot(script + "unset multiplot\n", svg.string());
}

void write_table(std::ofstream& html, const FleetWear& fleet) {
  html << "<table><tr><th>locomotive</th><th>wheel</th><th>runs</th><th>reprofiled</th>"
          "<th>wear now (mm)</th><th>rate (mm/1000 km) [95 %]</th><th>status</th>"
          "<th>days to warning</th><th>warning: km left [95 %]</th><th>warning date [95 %]</th>"
          "<th>critical date [95 %]</th></tr>\n";
  for (const WheelWear& w : fleet.wheels) {
    const auto date_range = [](const LimitForecast& f) {
      if (f.reached) return std::string("reached");
      return fmt::format("{} [{}, {}]", f.date.empty() ? "-" : f.date,
                         f.date_low.empty() ? "-" : f.date_low,
                         f.date_high.empty() ? "-" : f.date_high);
    };
    const double days = days_to_warning(w);
    html << (w.status == "ok" || w.status == "too few runs" ? "<tr>" : "<tr class='fault'>");
    html << fmt::format(
        "<td>{}</td><td>axle {} {}</td><td>{}</td><td>{}</td><td>{:.3f}</td><td>{}</td><td>{}</td>"
        "<td>{}</td><td>{}</td><td>{}</td><td>{}</td></tr>\n",
        coeffs::html_escape(w.wheel.locomotive), w.wheel.axle, w.wheel.side, w.runs.size(),
        w.reprofilings.size(), w.wear_now_mm,
        w.fit
            ? fmt::format("{:.4f} [{:.4f}, {:.4f}]", w.rate_mm_per_1000km, w.rate_low, w.rate_high)
            : std::string("-"),
        w.sensor_flag ? w.status + " (" + sensor_flag_text(*w.sensor_flag) + ")" : w.status,
        std::isfinite(days) ? fmt::format("{:.0f}", days) : "-",
        interval_text(w.warning.km, w.warning.km_low, w.warning.km_high, 0), date_range(w.warning),
        date_range(w.critical));
  }
  html << "</table>\n";
}

}  // namespace

void write_wear_report(const std::filesystem::path& dir, const FleetWear& fleet,
                       const std::string& generated_by, const std::string& sections_html) {
  std::map<std::string, Panels> locomotives;
  for (const WheelWear& w : fleet.wheels) {
    locomotives[w.wheel.locomotive][{w.wheel.axle, w.wheel.side}] = &w;
  }
  std::ofstream html(dir / "index.html", std::ios::binary);
  if (!html) throw std::runtime_error("cannot write " + (dir / "index.html").string());
  html << "<!DOCTYPE html>\n<html><head><meta charset='utf-8'><title>flange wear</title>\n"
          "<style>body{font-family:sans-serif;max-width:1100px;margin:1em auto}img{max-width:100%}"
          "table{border-collapse:collapse}td,th{padding:.2em .5em;border-bottom:1px solid #ddd;"
          "text-align:right}tr.fault{background:#fde0dd}</style></head><body>\n";
  html << "<h1>Flange wear of the fleet</h1>\n<p>" << coeffs::html_escape(generated_by)
       << "</p>\n<p>Wheels sorted by days to the warning clearance (" << fleet.warning_clearance_mm
       << " mm; critical " << fleet.critical_clearance_mm
       << " mm), soonest first. Rates and dates with their 95 % intervals; days from the "
          "locomotive's mean km per day; the intervals allow errors correlated from day to day "
          "and the km the locomotive has yet to run, the dates' also the season to come (carried "
          "forward from the history's) and the duties to come. A sensor drifting away from its axle "
          "partner is a sensor fault (red): its drift is fitted out of its wear. A rate whose "
          "interval lies below zero is no wear (wear only opens the clearance): a sensor fault "
          "when a drift explains it better, a missed reprofiling (red) when a step does. How "
          "each figure is made: docs/fleet.md.</p>\n";
  write_table(html, fleet);
  html << sections_html;
  int number = 0;
  for (const auto& [locomotive, panels] : locomotives) {
    // Numbered, not named: a locomotive's name may hold any character.
    const std::string svg = fmt::format("wear_{:02d}.svg", ++number);
    plot_locomotive(dir / svg, locomotive, panels, fleet);
    html << "<h2>" << coeffs::html_escape(locomotive) << "</h2><img src='"
         << coeffs::html_escape(svg) << "'>\n";
  }
  html << "</body></html>\n";
  html.close();
  if (!html) throw std::runtime_error("cannot write " + (dir / "index.html").string());
}

}  // namespace flange::host
