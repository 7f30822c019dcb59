// SPDX-License-Identifier: MIT
#include "diagnose_report.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <sstream>

#include "finding_text.h"
#include "gnuplot_runner.h"
#include "improved_twin_report.h"
#include "parallel_work.h"
#include "report_format.h"
#include "verdict_reasons.h"

namespace flange::diagnose {
namespace {

nlohmann::ordered_json finding_json(const EffectFinding& f) {
  return {{"name", f.name},
          {"params", params_json(f)},
          {"undetermined", f.undetermined},
          {"level", level_json(f)},
          {"resolution", resolution_json(f)},
          {"indistinguishable_from", f.indistinguishable_from},
          {"confidence", f.confidence},
          {"heldout_rms_before", f.heldout_rms_before},
          {"heldout_rms_after", f.heldout_rms_after},
          {"shrink_pct", f.shrink_pct},
          {"heldout_rms_without", f.heldout_rms_without},
          {"inclusion", f.inclusion},
          {"noise_type", f.noise_type},
          {"evidence", f.evidence}};
}

nlohmann::ordered_json test_json(const CorrelationTest& t) {
  return {{"max_lag", t.max_lag},         {"bound", t.bound},     {"lags_outside", t.lags_outside},
          {"lags_tested", t.lags_tested}, {"max_abs", t.max_abs}, {"passed", t.passed}};
}

nlohmann::ordered_json region_json(const RegionCell& c) {
  return {{"clearance_mm", {c.clearance_lo, c.clearance_hi}},
          {"temp_c", {c.temp_lo, c.temp_hi}},
          {"n", c.n},
          {"bias_v", c.bias_v},
          {"bias_ci95_v", {c.bias_lo, c.bias_hi}},
          {"rms_v", c.rms_v},
          {"rms_ci95_v", {c.rms_lo, c.rms_hi}}};
}

nlohmann::ordered_json adc_grid_json(const AdcGrid& g) {
  return {{"lsb_v", g.lsb_v},
          {"lowest_v", g.lowest_v},
          {"highest_v", g.highest_v},
          {"codes_used", g.codes_used},
          {"codes_spanned", g.codes_spanned},
          {"share_on_grid", g.share_on_grid},
          {"bits", g.bits},
          {"v_min", g.v_min},
          {"v_max", g.v_max},
          {"usual_range", g.usual_range},
          {"quantisation_std_v", g.lsb_v / std::sqrt(12.0)}};
}

// At most about 4000 points per trace: every k-th sample.
std::vector<std::vector<double>> decimated(const std::vector<std::vector<double>>& columns) {
  const std::size_t n = columns.front().size();
  const std::size_t stride = std::max<std::size_t>(1, n / 4000);
  std::vector<std::vector<double>> out(columns.size());
  for (std::size_t i = 0; i < n; i += stride) {
    for (std::size_t c = 0; c < columns.size(); ++c) out[c].push_back(columns[c][i]);
  }
  return out;
}

// An explicit range for an axis whose values are all one (a constant clearance, temperature or
// gap), which gnuplot would otherwise widen with a warning: 1 % of the value, at least 1e-3.
std::string range_if_flat(const char* axis, const std::vector<double>& values) {
  std::vector<double> finite;
  for (double v : values) {
    if (std::isfinite(v)) finite.push_back(v);
  }
  if (finite.empty()) return "";
  const auto [lo, hi] = std::minmax_element(finite.begin(), finite.end());
  if (*hi - *lo > 1e-6 * std::max(1.0, std::abs(*hi))) return "";
  const double pad = std::max(0.01 * std::abs(*lo), 1e-3);
  return fmt::format("set {}range [{:.9g}:{:.9g}]\n", axis, *lo - pad, *hi + pad);
}

void plot_region(const std::filesystem::path& dir, const DiagnosisDetail& d) {
  std::string script = coeffs::gnuplot_svg_terminal(dir / "region.svg", 1000, 450);
  for (int which = 0; which < 2; ++which) {
    script += which == 0 ? "$bias << EOD\n" : "$rms << EOD\n";
    // 5 clearance cells per temperature row (diagnosis.cpp's grid); blank line between rows.
    for (std::size_t k = 0; k < d.regions.size(); ++k) {
      const RegionCell& c = d.regions[k];
      const double value = which == 0 ? c.bias_v : c.rms_v;
      script += fmt::format("{:.6g} {:.6g} {}\n", 0.5 * (c.clearance_lo + c.clearance_hi),
                            0.5 * (c.temp_lo + c.temp_hi),
                            c.n > 0 ? fmt::format("{:.6g}", value) : "NaN");
      if (k + 1 < d.regions.size() && d.regions[k + 1].temp_lo != c.temp_lo) script += "\n";
    }
    script += "EOD\n";
  }
  std::vector<double> clearance, temp, bias, rms;
  for (const RegionCell& c : d.regions) {
    clearance.push_back(0.5 * (c.clearance_lo + c.clearance_hi));
    temp.push_back(0.5 * (c.temp_lo + c.temp_hi));
    if (c.n == 0) continue;
    bias.push_back(c.bias_v);
    rms.push_back(c.rms_v);
  }
  script +=
      "set multiplot layout 1,2 title 'voltage gap (real - sim) by operating region, V'\n"
      "set xlabel 'reference clearance (mm)'\nset ylabel 'temperature (C)'\n";
  script += range_if_flat("x", clearance) + range_if_flat("y", temp);
  script += "set title 'bias'\nset palette defined (-1 '#2c7bb6', 0 '#ffffff', 1 '#d7191c')\n" +
            range_if_flat("cb", bias) + "plot $bias using 1:2:3 with image notitle\n";
  script += std::string(
                "set title 'RMS'\nset palette defined (0 '#ffffff', 1 '#fdae61', 2 '#d7191c')\n") +
            "set autoscale cb\n" + range_if_flat("cb", rms) +
            "plot $rms using 1:2:3 with image notitle\nunset multiplot\n";
  coeffs::run_gnuplot(script, (dir / "region.svg").string());
}

void plot_spectrum(const std::filesystem::path& dir, const DiagnosisDetail& d) {
  std::string script = coeffs::gnuplot_svg_terminal(dir / "spectrum.svg", 900, 450);
  std::vector<double> f, db, noise_db;
  for (std::size_t k = 1; k < d.gap_psd.value.size(); ++k) {
    f.push_back(d.gap_psd.frequency_hz[k]);
    db.push_back(10.0 * std::log10(std::max(d.gap_psd.value[k], 1e-30)));
    noise_db.push_back(10.0 * std::log10(std::max(d.noise_psd, 1e-30)));
  }
  script += coeffs::gnuplot_data_block("psd", {f, db, noise_db});
  std::vector<double> levels = db;
  levels.insert(levels.end(), noise_db.begin(), noise_db.end());
  script += range_if_flat("y", levels);
  if (d.band_hz) {
    script += fmt::format(
        "set object 1 rect from {},graph 0 to {},graph 1 fc rgb '#fde0dd' fs solid 0.6 behind\n",
        d.band_hz->first, d.band_hz->second);
  }
  script +=
      "set xlabel 'frequency (Hz)'\nset ylabel 'PSD (dB re 1 V^2/Hz)'\nset key top right\n"
      "plot $psd using 1:2 with lines lw 2 lc rgb '#1f77b4' title 'voltage gap (calibration "
      "part)', $psd using 1:3 with lines dt 2 lc rgb '#444444' title 'white noise of the twin'\n";
  coeffs::run_gnuplot(script, (dir / "spectrum.svg").string());
}

void plot_time(const std::filesystem::path& dir, const DiagnosisDetail& d) {
  std::string script = coeffs::gnuplot_svg_terminal(dir / "time.svg", 1000, 450);
  script += coeffs::gnuplot_data_block("gap", decimated({d.t_s, d.gap_v}));
  std::vector<double> st, sm;
  for (const TimeSegment& s : d.segments) {
    st.insert(st.end(), {s.t_start_s, s.t_end_s});
    sm.insert(sm.end(), {s.mean_v, s.mean_v});
  }
  script += coeffs::gnuplot_data_block("segments", {st, sm});
  script += range_if_flat("y", d.gap_v);
  if (d.segments.empty()) {
    script +=
        "set xlabel 'time (s)'\nset ylabel 'voltage gap (V)'\nset key outside bottom center "
        "horizontal\nplot $gap using 1:2 with lines lc rgb '#aaaaaa' title 'real - sim (no "
        "change points: nothing to locate)'\n";
    coeffs::run_gnuplot(script, (dir / "time.svg").string());
    return;
  }
  script +=
      "set xlabel 'time (s)'\nset ylabel 'voltage gap (V)'\nset key outside bottom center "
      "horizontal\nplot $gap using 1:2 with lines lc rgb '#aaaaaa' title 'real - sim', "
      "$segments using 1:2 with lines lw 3 lc rgb '#d62728' title 'segment means (change "
      "points)'\n";
  coeffs::run_gnuplot(script, (dir / "time.svg").string());
}

void plot_heldout(const std::filesystem::path& dir, const DiagnosisDetail& d) {
  std::string script = coeffs::gnuplot_svg_terminal(dir / "heldout.svg", 1000, 450);
  script += coeffs::gnuplot_data_block(
      "ho", decimated({d.heldout_t_s, d.heldout_gap_before_v, d.heldout_gap_after_v}));
  std::vector<double> both = d.heldout_gap_before_v;
  both.insert(both.end(), d.heldout_gap_after_v.begin(), d.heldout_gap_after_v.end());
  script += range_if_flat("y", both);
  script +=
      "set xlabel 'time (s)'\nset ylabel 'voltage gap on held-out data (V)'\nset key outside "
      "bottom center horizontal\nplot $ho using 1:2 with lines lc rgb '#bbbbbb' title 'before "
      "(twin as given)', $ho using 1:3 with lines lc rgb '#1f77b4' title 'after (selected "
      "effects added)'\n";
  coeffs::run_gnuplot(script, (dir / "heldout.svg").string());
}

nlohmann::ordered_json segments_json(const std::vector<TimeSegment>& segments) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const TimeSegment& s : segments) {
    out.push_back({{"t_start_s", s.t_start_s}, {"t_end_s", s.t_end_s}, {"mean_v", s.mean_v}});
  }
  return out;
}

// Where the gap lies: its stage, region, band and segments, and the residual tests.
nlohmann::ordered_json where_json(const Diagnosis& g, const DiagnosisDetail& d) {
  nlohmann::ordered_json coherences = nlohmann::ordered_json::object();
  for (const InputCoherence& c : d.coherences) {
    coherences[c.input] = {{"in_band", c.in_band}, {"peak", c.peak}, {"peak_hz", c.peak_hz}};
  }
  return {{"stage", g.stage},
          {"region",
           d.where_region ? region_json(d.regions[*d.where_region]) : nlohmann::ordered_json()},
          {"band_hz", d.band_hz ? nlohmann::ordered_json{d.band_hz->first, d.band_hz->second}
                                : nlohmann::ordered_json()},
          {"segments", segments_json(d.segments)},
          {"coherence", coherences},
          {"whiteness", test_json(d.whiteness)},
          {"cross_correlation",
           {{"temperature", test_json(d.vs_temperature)},
            {"temperature_rate", test_json(d.vs_temperature_rate)},
            {"clearance", test_json(d.vs_clearance)}}}};
}

nlohmann::ordered_json stages_json(const std::vector<StageGap>& stages) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const StageGap& s : stages) {
    out.push_back({{"name", s.name},
                   {"unit", s.unit},
                   {"gap_rms", s.gap_rms},
                   {"noise_floor", s.noise_floor},
                   {"real_error_rms", s.real_error_rms},
                   {"sim_error_rms", s.sim_error_rms},
                   {"significant", s.significant},
                   {"note", s.note}});
  }
  return out;
}

nlohmann::ordered_json findings_json(const std::vector<EffectFinding>& findings) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const EffectFinding& f : findings) out.push_back(finding_json(f));
  return out;
}

// How far the gap shrinks on the held-out data: over it, in the region, in the band, in its worst
// window and within the calibration's ranges.
nlohmann::ordered_json how_far_json(const HowFar& h) {
  return {{"heldout_rms_before_v", h.rms_before},
          {"heldout_rms_after_v", h.rms_after},
          {"heldout_max_before_v", h.max_before},
          {"heldout_max_after_v", h.max_after},
          {"region_rms_before_v", h.region_rms_before},
          {"region_rms_after_v", h.region_rms_after},
          {"region_heldout_samples", h.region_samples},
          {"band_rms_before_v", h.band_rms_before},
          {"band_rms_after_v", h.band_rms_after},
          {"worst_window",
           {{"from_s", h.worst_window.from_s},
            {"to_s", h.worst_window.to_s},
            {"rms_after_v", h.worst_window.rms_v}}},
          {"within_calibration",
           {{"heldout_samples", h.within_calibration_samples},
            {"rms_before_v", h.within_calibration_rms_before},
            {"rms_after_v", h.within_calibration_rms_after}}}};
}

}  // namespace

nlohmann::ordered_json diagnosis_json(const DiagnosisResult& result, const std::string& real,
                                      const std::string& heldout) {
  const Diagnosis& g = result.diagnosis;
  const DiagnosisDetail& d = result.detail;
  nlohmann::ordered_json names = nlohmann::ordered_json::array();
  for (const EffectFinding& f : g.effects) names.push_back(f.name);
  nlohmann::ordered_json j;
  j["format"] = "flange-diagnosis/1";
  j["real"] = real;
  j["heldout"] = heldout;
  j["verdict"] = {
      {"status", status_text(g.status)},
      {"scope", g.scope.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(g.scope)},
      {"effects", names},
      {"reasons", d.reasons}};
  j["degenerate"] = g.degenerate;
  j["next_measurement"] = g.next_measurement;
  j["where"] = where_json(g, d);
  j["stages"] = stages_json(d.stages);
  j["effects"] = findings_json(g.effects);
  j["partial_effects"] = findings_json(d.partial);
  j["nearest"] = g.nearest ? finding_json(*g.nearest) : nlohmann::ordered_json();
  j["how_far"] = how_far_json(d.how_far);
  nlohmann::ordered_json regions = nlohmann::ordered_json::array();
  for (const RegionCell& c : d.regions) regions.push_back(region_json(c));
  j["regions"] = regions;
  j["noise"] = {{"voltage_std_v", d.noise_std_v},
                {"source", d.noise_source},
                {"analog_std_v", d.white_noise.analog_std_v},
                {"grid_aware", d.white_noise.grid_aware}};
  j["adc_grid"] = d.adc_grid ? adc_grid_json(*d.adc_grid) : nlohmann::ordered_json();
  j["fs_hz"] = d.fs_hz;
  j["sessions"] = {{"clock", g.clock},
                   {"heldout_starts_after_s",
                    g.heldout_starts_after_s ? nlohmann::ordered_json(*g.heldout_starts_after_s)
                                             : nlohmann::ordered_json()}};
  j["improved_twin"] = improved_twin_json(result.improved_twin);
  return j;
}

std::string diagnosis_summary(const DiagnosisResult& result) {
  const Diagnosis& g = result.diagnosis;
  const DiagnosisDetail& d = result.detail;
  std::ostringstream text;
  const std::string names = verdict_names(g.effects);
  text << "verdict: " << status_text(g.status) << (names.empty() ? "" : " by " + names)
       << (g.scope.empty() ? "" : ", " + g.scope) << "\n";
  for (const std::string& what : g.degenerate) text << "  data: " << what << "\n";
  text << fmt::format("  where: stage {}", g.stage);
  if (d.where_region) {
    const RegionCell& c = d.regions[*d.where_region];
    text << fmt::format("; region {:.2f}-{:.2f} mm x {:.1f}-{:.1f} C (bias {:.4f} V, RMS {:.4f} V)",
                        c.clearance_lo, c.clearance_hi, c.temp_lo, c.temp_hi, c.bias_v, c.rms_v);
  }
  if (d.band_hz)
    text << fmt::format("; band {:.3f}-{:.3f} Hz", d.band_hz->first, d.band_hz->second);
  text << fmt::format("; {} time segment(s)\n", d.segments.size());
  for (const EffectFinding& f : g.effects.empty() ? d.partial : g.effects) {
    const std::string params = params_text(f);
    text << fmt::format(
        "  {} {}: {} held-out RMS {:.4f} -> {:.4f} V ({:.1f} %), inclusion {:.2f}{}{}\n",
        g.effects.empty() ? "partial" : "effect", f.name, params, f.heldout_rms_before,
        f.heldout_rms_after, f.shrink_pct, f.inclusion,
        g.effects.empty() ? "" : fmt::format(", confidence {:.2f}", f.confidence),
        f.noise_type ? " (noise-type)" : "");
  }
  if (g.nearest) {
    text << fmt::format("  nearest: {} ({})\n", g.nearest->name, g.nearest->evidence);
  }
  text << fmt::format(
      "  how far: held-out RMS {:.4f} -> {:.4f} V, max {:.4f} -> {:.4f} V; noise {:.4f} V; "
      "most left in {:.1f}-{:.1f} s: {:.4f} V RMS\n",
      d.how_far.rms_before, d.how_far.rms_after, d.how_far.max_before, d.how_far.max_after,
      d.noise_std_v, d.how_far.worst_window.from_s, d.how_far.worst_window.to_s,
      d.how_far.worst_window.rms_v);
  for (const std::string& next : g.next_measurement) text << "  next: " << next << "\n";
  if (d.adc_grid) {
    text << fmt::format(
        "  converter grid: LSB {:.4g} mV, codes {:.6g} to {:.6g} V ({} used); analog noise {:.4f} "
        "V{}\n",
        1e3 * d.adc_grid->lsb_v, d.adc_grid->lowest_v, d.adc_grid->highest_v,
        d.adc_grid->codes_used, d.white_noise.analog_std_v,
        d.white_noise.grid_aware ? " (fitted on the grid)" : "");
  }
  return text.str();
}

void write_diagnosis_report(const std::filesystem::path& dir, const DiagnosisResult& result,
                            const std::string& title) {
  const DiagnosisDetail& d = result.detail;
  // Four gnuplot processes, as many at once as worker threads are free: on a 6 Hz pair they
  // are a fifth of the command's time.
  const std::array plots{plot_region, plot_spectrum, plot_time, plot_heldout};
  run_in_parallel(static_cast<int>(plots.size()), 0,
                  [&](int i) { plots[static_cast<std::size_t>(i)](dir, d); });
  std::ofstream html(dir / "report.html", std::ios::binary);
  if (!html) throw std::runtime_error("cannot write " + (dir / "report.html").string());
  html << "<!DOCTYPE html>\n<html><head><meta charset='utf-8'><title>flange diagnose: "
       << coeffs::html_escape(title)
       << "</title>\n<style>body{font-family:sans-serif;max-width:1050px;"
       << "margin:1em auto}pre{background:#f4f4f4;padding:.8em}img{max-width:100%}"
       << "td,th{padding:2px 8px;text-align:right}</style></head><body>\n";
  html << "<h1>flange diagnose</h1>\n<pre>" << coeffs::html_escape(diagnosis_summary(result))
       << "</pre>\n";
  html << "<h2>Verdict</h2><ul>";
  for (const std::string& r : d.reasons) html << "<li>" << coeffs::html_escape(r) << "</li>";
  if (result.diagnosis.nearest) {
    const EffectFinding& n = *result.diagnosis.nearest;
    html << "<li>nearest library effect: <b>" << coeffs::html_escape(n.name) << "</b>, "
         << coeffs::html_escape(n.evidence) << "</li>";
  }
  html << "</ul>\n<h2>The gap at each stage</h2><table><tr><th>stage</th><th>gap RMS</th>"
          "<th>noise floor</th><th>real error</th><th>sim error</th><th>significant</th></tr>\n";
  for (const StageGap& s : d.stages) {
    html << fmt::format(
        "<tr><td>{}</td><td>{:.4g} {}</td><td>{:.4g}</td><td>{:.4g}</td>"
        "<td>{:.4g}</td><td>{}</td></tr>\n",
        s.name, s.gap_rms, s.unit, s.noise_floor, s.real_error_rms, s.sim_error_rms,
        s.significant ? "yes" : "no");
  }
  html << "</table><p>Noise floor: the same gap for the twin with its white noise against the "
          "twin without. Real/sim error: against the reference clearance.</p>\n";
  html << "<h2>By operating region</h2><p>Bias and RMS of the voltage gap per clearance x "
          "temperature cell of the calibration part; diagnosis.json gives 95 % block-bootstrap "
          "intervals.</p><img src='region.svg'>\n";
  html << "<h2>By frequency</h2><p>Welch PSD of the voltage gap against the twin's white noise; "
          "the shaded band is where the gap exceeds twice the noise.</p><img src='spectrum.svg'>\n";
  html << "<h2>Over time</h2><p>The voltage gap and the means of the segments found by binary "
          "segmentation.</p><img src='time.svg'>\n";
  html << "<h2>Before and after, held-out data</h2><img src='heldout.svg'>\n";
  html << improved_twin_html(result.improved_twin);
  html << "</body></html>\n";
}

}  // namespace flange::diagnose
