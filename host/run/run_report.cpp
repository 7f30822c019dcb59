// SPDX-License-Identifier: MIT
#include "run_report.h"

#include <fmt/format.h>

#include <cmath>
#include <complex>
#include <fstream>
#include <numbers>
#include <sstream>

#include "filter_json.h"
#include "gnuplot_runner.h"
#include "report_format.h"

namespace flange::host {

std::string run_summary_text(const RunOptions& options, const RunSummary& summary) {
  std::ostringstream text;
  text << fmt::format("run: {} through {} (engine {}, fs {:.6g} Hz)\n", options.input,
                      options.coeffs, summary.engine, summary.fs_hz);
  text << fmt::format(
      "  rows read {}, flagged {} (bad {}, outside calibration {}, clipped {}, saturated {})\n",
      summary.rows_read, summary.rows_flagged, summary.bad_rows, summary.outside_calibration,
      summary.clipped_samples, summary.saturated_outputs);
  for (const std::string& message : summary.bad_row_messages) {
    text << "  bad row: " << message << "\n";
  }
  if (summary.engine == "rtl") {
    text << fmt::format("  rtl checked against the model: {} mismatches\n", summary.rtl_mismatches);
  }
  text << fmt::format("  alarm events {}, final level {}\n", summary.alarm_events.size(),
                      summary.final_alarm);
  for (std::size_t k = 0; k < summary.alarm_events.size() && k < 10; ++k) {
    text << fmt::format("    t = {:.2f} s: {}\n", summary.alarm_events[k].t_s,
                        summary.alarm_events[k].what);
  }
  if (summary.alarm_events.size() > 10) {
    text << fmt::format("    ... {} more in the output CSV's alarm column\n",
                        summary.alarm_events.size() - 10);
  }
  text << fmt::format("  filter group delay at DC: {:.3f} s ({} samples)\n", summary.group_delay_s,
                      summary.delay_samples);
  if (summary.has_reference) {
    text << fmt::format("  error before filtering: MAE {:.4f} mm, RMSE {:.4f} mm, max {:.4f} mm\n",
                        summary.before.mae(), summary.before.rmse(), summary.before.max_abs);
    text << fmt::format(
        "  error after filtering:  MAE {:.4f} mm, RMSE {:.4f} mm, max {:.4f} mm (reference "
        "delayed by the group delay; first {} samples of start-up left out)\n",
        summary.after.mae(), summary.after.rmse(), summary.after.max_abs, summary.settle_samples);
  } else {
    text << "  no clearance reference in the input: errors not computed\n";
  }
  return text.str();
}

namespace {

void plot_traces(const std::filesystem::path& dir, const RunTrace& trace) {
  std::string script = coeffs::gnuplot_svg_terminal(dir / "traces.svg", 1000, 500);
  script += coeffs::gnuplot_data_block(
      "trace", {trace.t_s, trace.raw_mm, trace.filt_mm, trace.reference_mm, trace.temp_c});
  script +=
      "set xlabel 'time (s)'\nset ylabel 'clearance (mm)'\nset y2label 'temperature (C)'\n"
      "set y2tics\nset key outside bottom center horizontal\n";
  script +=
      "plot $trace using 1:2 with lines lc rgb '#bbbbbb' title 'raw (after regression)', "
      "$trace using 1:4 with lines lw 2 lc rgb '#2ca02c' title 'reference', "
      "$trace using 1:3 with lines lw 1.5 lc rgb '#1f77b4' title 'filtered', "
      "$trace using 1:5 axes x1y2 with lines dt 2 lc rgb '#d62728' title 'temperature'\n";
  coeffs::run_gnuplot(script, (dir / "traces.svg").string());
}

void plot_regions(const std::filesystem::path& dir, const RunTrace& trace) {
  std::string script = coeffs::gnuplot_svg_terminal(dir / "error_by_region.svg", 1000, 450);
  for (int which = 0; which < 2; ++which) {
    const auto& cells = which == 0 ? trace.region_before : trace.region_after;
    script += fmt::format("${} << EOD\n", which == 0 ? "before" : "after");
    for (int t = 0; t < RunTrace::kTempBins; ++t) {
      for (int c = 0; c < RunTrace::kClearanceBins; ++c) {
        const ErrorStats& cell = cells[static_cast<std::size_t>(t * RunTrace::kClearanceBins + c)];
        script += fmt::format("{} {} {}\n", c + 0.5, t * 10 + 5,
                              cell.n > 0 ? fmt::format("{:.6g}", cell.mae()) : "NaN");
      }
      script += "\n";
    }
    script += "EOD\n";
  }
  script +=
      "set multiplot layout 1,2 title 'mean absolute error by clearance and temperature (mm)'\n"
      "set xlabel 'reference clearance (mm)'\nset ylabel 'temperature (C)'\n"
      "set xrange [0:12]\nset yrange [0:120]\nset palette defined (0 '#ffffff', 1 '#fdae61', 2 "
      "'#d7191c')\nset cbrange [0:*]\n";
  script += "set title 'before filtering'\nplot $before using 1:2:3 with image pixels notitle\n";
  script += "set title 'after filtering'\nplot $after using 1:2:3 with image pixels notitle\n";
  script += "unset multiplot\n";
  coeffs::run_gnuplot(script, (dir / "error_by_region.svg").string());
}

void plot_response(const std::filesystem::path& dir, const std::string& coeffs_path) {
  const model::FloatDesign design = model::load_float_design(coeffs_path);
  const model::CoreConfig core = model::load_core_config(coeffs_path);
  std::vector<double> f, float_db, quant_db;
  const double nyquist = design.fs_hz / 2.0;
  for (int i = 0; i <= 600; ++i) {
    const double freq = nyquist * std::pow(1e-4, 1.0 - i / 600.0);
    const std::complex<double> w = std::polar(1.0, -2.0 * std::numbers::pi * freq / design.fs_hz);
    std::complex<double> h_float(design.leftover_gain, 0.0);
    for (const auto& row : design.sos) {
      h_float *= (row[0] + w * (row[1] + w * row[2])) / (row[3] + w * (row[4] + w * row[5]));
    }
    std::complex<double> h_quant(design.leftover_gain, 0.0);
    const int m = core.section_order;
    for (int k = 0; k < core.num_sections; ++k) {
      std::complex<double> num(0.0, 0.0), den(0.0, 0.0), power(1.0, 0.0);
      const std::vector<double> b = core.b_values(k);
      const std::vector<double> a = core.a_values(k);
      for (int j = 0; j <= m; ++j) {
        num += b[static_cast<std::size_t>(j)] * power;
        den += a[static_cast<std::size_t>(j)] * power;
        power *= w;
      }
      h_quant *= num / den;
    }
    f.push_back(freq);
    float_db.push_back(std::max(-200.0, 20.0 * std::log10(std::abs(h_float))));
    quant_db.push_back(std::max(-200.0, 20.0 * std::log10(std::abs(h_quant))));
  }
  std::string script = coeffs::gnuplot_svg_terminal(dir / "response.svg", 900, 450);
  script += coeffs::gnuplot_data_block("response", {f, float_db, quant_db});
  script +=
      "set logscale x\nset xlabel 'frequency (Hz)'\nset ylabel 'magnitude (dB)'\n"
      "set yrange [-120:5]\nset key bottom left\n"
      "plot $response using 1:2 with lines lw 2 lc rgb '#1f77b4' title 'float design', "
      "$response using 1:3 with lines dt 2 lw 1.5 lc rgb '#d62728' title 'quantised (ROM)'\n";
  coeffs::run_gnuplot(script, (dir / "response.svg").string());
}

void plot_spectra(const std::filesystem::path& dir, const RunTrace& trace) {
  const std::vector<double> raw = trace.spectrum_raw->psd();
  const std::vector<double> filt = trace.spectrum_filt->psd();
  std::string script = coeffs::gnuplot_svg_terminal(dir / "spectra.svg", 900, 450);
  if (raw.empty()) {
    script +=
        "set label 'recording shorter than one 256-sample segment: no spectrum' at graph "
        "0.5,0.5 center\n"
        // gnuplot refuses a plot with no defined point unless both ranges are given.
        "set xrange [0:1]\nset yrange [0:1]\nunset tics\nplot NaN notitle\n";
  } else {
    std::vector<double> f = trace.spectrum_raw->frequencies_hz();
    std::vector<double> raw_db, filt_db;
    for (std::size_t k = 0; k < raw.size(); ++k) {
      raw_db.push_back(10.0 * std::log10(std::max(raw[k], 1e-30)));
      filt_db.push_back(10.0 * std::log10(std::max(filt[k], 1e-30)));
    }
    f.erase(f.begin());  // DC is removed per segment; the log axis cannot show it anyway
    raw_db.erase(raw_db.begin());
    filt_db.erase(filt_db.begin());
    script += coeffs::gnuplot_data_block("psd", {f, raw_db, filt_db});
    script +=
        "set logscale x\nset xlabel 'frequency (Hz)'\nset ylabel 'PSD (dB re 1 mm^2/Hz)'\n"
        "plot $psd using 1:2 with lines lc rgb '#888888' title 'before filtering', "
        "$psd using 1:3 with lines lw 2 lc rgb '#1f77b4' title 'after filtering'\n";
  }
  coeffs::run_gnuplot(script, (dir / "spectra.svg").string());
}

}  // namespace

void write_run_report(const std::filesystem::path& dir, const RunOptions& options,
                      const RunSummary& summary, const RunTrace& trace) {
  std::filesystem::create_directories(dir);
  plot_traces(dir, trace);
  plot_regions(dir, trace);
  plot_response(dir, options.coeffs);
  plot_spectra(dir, trace);
  std::ofstream html(dir / "index.html", std::ios::binary);
  if (!html) throw std::runtime_error("cannot write " + (dir / "index.html").string());
  html << "<!DOCTYPE html>\n<html><head><meta charset='utf-8'><title>flange run: "
       << coeffs::html_escape(options.input) << "</title>\n<style>body{font-family:sans-serif;"
       << "max-width:1050px;margin:1em auto}pre{background:#f4f4f4;padding:.8em}"
       << "img{max-width:100%}</style></head><body>\n";
  html << "<h1>flange run</h1>\n<pre>" << coeffs::html_escape(run_summary_text(options, summary))
       << "</pre>\n";
  html << "<h2>Clearance over time</h2><p>Raw: the regression's clearance before the filter. "
          "Filtered: after the "
       << summary.engine
       << " engine. Reference: the recording's "
          "clearance_mm (micrometer or simulated truth). Decimated to at most "
       << RunTrace::kMaxPoints << " points.</p><img src='traces.svg'>\n";
  html << "<h2>Error by clearance and temperature</h2><p>Mean absolute error per cell; white "
          "cells had no data. After filtering, the reference is delayed by the filter's group "
          "delay.</p><img src='error_by_region.svg'>\n";
  html << "<h2>The filter</h2><p>" << coeffs::html_escape(options.coeffs)
       << ": the float design and the quantised coefficients in the ROM.</p>"
          "<img src='response.svg'>\n";
  html << "<h2>Spectra before and after filtering</h2><p>Welch estimate, 256-sample Hann "
          "segments, half overlapping.</p><img src='spectra.svg'>\n";
  html << "</body></html>\n";
}

}  // namespace flange::host
