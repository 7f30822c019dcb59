// SPDX-License-Identifier: MIT
#include "hw_diagnose_report.h"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>
#include <ostream>
#include <sstream>
#include <stdexcept>

#include "gnuplot_runner.h"
#include "report_format.h"

namespace flange::diagnose {
namespace fs = std::filesystem;

namespace {

std::string effect_label(const GapStep& step) {
  return step.added ? model::effect_name(*step.added) : "none (float design)";
}

std::string snr_text(const GapFigures& g) {
  return g.snr_db ? fmt::format("{:.1f}", *g.snr_db) : "inf";
}

// A number for display: rounding noise below the printed precision shows as 0, not -0.
std::string lsb(double v) {
  const std::string text = fmt::format("{:.4g}", v);
  return text == "-0" ? "0" : text;
}

const GapStep& last(const HwDiagnosis& d) { return d.attribution.steps.back(); }

void plot_steps(const HwDiagnosis& d, const fs::path& dir) {
  const fs::path svg = dir / "gap_steps.svg";
  std::string script = coeffs::gnuplot_svg_terminal(svg, 900, 420, false, false);
  script +=
      "set title 'Gap to the hardware after each step (output LSB)'\nset style data histograms\n"
      "set style histogram clustered gap 1\nset style fill solid 0.8 border -1\nset logscale y\n"
      "set yrange [1e-4:*]\nset ylabel 'gap, LSB (zero drawn at 1e-4)'\nset xtics rotate by -25\n"
      "set key top right\nset grid ytics\n$steps << EOD\n";
  for (std::size_t i = 0; i < d.attribution.steps.size(); ++i) {
    const GapStep& s = d.attribution.steps[i];
    script += fmt::format("\"{}: {}\" {:.9g} {:.9g}\n", i, effect_label(s),
                          std::max(s.gap.rms_lsb, 1e-4), std::max(s.gap.max_lsb, 1e-4));
  }
  script += "EOD\nplot $steps using 2:xtic(1) title 'RMS', '' using 3 title 'max'\n";
  coeffs::run_gnuplot(script, svg.string());
}

void plot_traces(const HwDiagnosis& d, const fs::path& dir) {
  const fs::path svg = dir / "traces.svg";
  const std::size_t n = std::min<std::size_t>(d.real.size(), 2000);
  std::string script = coeffs::gnuplot_svg_terminal(svg, 1000, 700, false, false);
  script += "set multiplot layout 2,1\nset grid\nset key outside right\nset xlabel 'sample'\n";
  script += "$data << EOD\n";
  const auto& steps = d.attribution.steps;
  for (std::size_t k = 0; k < n; ++k) {
    script += fmt::format("{} {:.9g} {:.9g}", k, steps.front().output[k], d.real[k]);
    for (const GapStep& s : steps) script += fmt::format(" {:.9g}", d.real[k] - s.output[k]);
    script += "\n";
  }
  script += "EOD\n";
  script += fmt::format(
      "set title 'Output (first {} samples), LSB'\nplot $data using 1:2 with lines title 'float "
      "design', '' using 1:3 with lines title '{}'\n",
      n, d.mode == "rtl" ? "Verilated RTL" : "printed coefficients");
  script += "set title 'Gap (real - model) after each step, LSB'\nplot ";
  for (std::size_t i = 0; i < steps.size(); ++i) {
    script += fmt::format("{}$data using 1:{} with lines title '{}: {}'", i == 0 ? "" : ", ", i + 4,
                          i, effect_label(steps[i]));
  }
  script += "\nunset multiplot\n";
  coeffs::run_gnuplot(script, svg.string());
}

nlohmann::json to_json(const HwDiagnosis& d) {
  nlohmann::json j;
  j["coeffs"] = d.coeffs;
  j["stimulus"] = d.stimulus;
  j["seed"] = d.seed;
  j["samples"] = d.real.size();
  j["mode"] = d.mode;
  if (!d.printed_source.empty()) j["printed"] = d.printed_source;
  j["unit"] = fmt::format("LSB of Q1.{}", d.sample_width - 1);
  nlohmann::json steps = nlohmann::json::array();
  for (std::size_t i = 0; i < d.attribution.steps.size(); ++i) {
    const GapStep& s = d.attribution.steps[i];
    nlohmann::json step = {{"step", i},
                           {"effect_added", s.added ? model::effect_name(*s.added) : "none"},
                           {"gap_rms_lsb", s.gap.rms_lsb},
                           {"gap_max_lsb", s.gap.max_lsb},
                           {"snr_db", s.gap.snr_db ? nlohmann::json(*s.gap.snr_db) : nullptr},
                           {"samples_differing", s.gap.differing},
                           {"shrink_pct", s.shrink_pct},
                           {"changed_output", s.changed},
                           {"max_pole_radius", s.poles.max_radius},
                           {"poles_outside", s.poles.outside}};
    nlohmann::json on = nlohmann::json::array();
    for (model::FixedPointEffect e : s.effects.list()) on.push_back(model::effect_name(e));
    step["effects_on"] = on;
    steps.push_back(step);
  }
  j["steps"] = steps;
  j["unstable_step"] =
      d.attribution.unstable_step ? nlohmann::json(*d.attribution.unstable_step) : nullptr;
  if (d.mode == "rtl") {
    j["staged_vs_model_mismatches"] = d.staged_vs_model;
    j["model_vs_rtl_mismatches"] = d.model_vs_rtl;
    j["runner_mismatches"] = d.runner_mismatches;
  }
  j["diverged_at"] = d.diverged_at ? nlohmann::json(*d.diverged_at) : nullptr;
  j["explained"] = d.explained();
  j["verdict"] = d.final_line();
  return j;
}

std::string table_text(const HwDiagnosis& d) {
  std::string text =
      fmt::format("{:>4}  {:<22} {:>12} {:>12} {:>8} {:>9} {:>9} {:>10}\n", "step", "effect added",
                  "gap RMS LSB", "gap max LSB", "SNR dB", "shrink %", "differ %", "max |z|");
  for (std::size_t i = 0; i < d.attribution.steps.size(); ++i) {
    const GapStep& s = d.attribution.steps[i];
    const double differ =
        100.0 * static_cast<double>(s.gap.differing) / static_cast<double>(d.real.size());
    std::string note = s.poles.stable() ? "" : "  UNSTABLE";
    if (i > 0 && !s.changed) note += "  (inactive on this stimulus)";
    text += fmt::format("{:>4}  {:<22} {:>12} {:>12} {:>8} {:>9} {:>9.1f} {:>10.6f}{}\n", i,
                        effect_label(s), lsb(s.gap.rms_lsb), lsb(s.gap.max_lsb), snr_text(s.gap),
                        i == 0 ? "-" : fmt::format("{:.1f}", s.shrink_pct), differ,
                        s.poles.max_radius, note);
  }
  return text;
}

}  // namespace

bool HwDiagnosis::explained() const {
  if (attribution.unstable_step) return false;
  const GapStep& end = attribution.steps.back();
  if (end.gap.differing != 0) return false;
  if (mode == "rtl") return staged_vs_model == 0 && model_vs_rtl == 0 && runner_mismatches == 0;
  return true;
}

std::string HwDiagnosis::final_line() const {
  const std::size_t n = real.size();
  if (const auto k = attribution.unstable_step) {
    const GapStep& s = attribution.steps[*k];
    const std::string what =
        mode == "printed"
            ? fmt::format("coefficient rounding to the printed values ({})", printed_source)
            : (s.added ? model::effect_description(*s.added) : "the float design");
    return fmt::format(
        "diagnose --hw: {} alone (step {}) makes the filter unstable: {} pole(s) on or outside the "
        "unit circle (max |z| = {:.4f}){}",
        what, *k, s.poles.outside, s.poles.max_radius,
        diverged_at
            ? fmt::format("; its output passes 10^6 x full scale at sample {}", *diverged_at)
            : "");
  }
  const GapStep& end = last(*this);
  if (mode == "printed") {
    return fmt::format(
        "diagnose --hw: the printed coefficients ({}) are stable (max |z| = {:.6f}); coefficient "
        "rounding explains the whole gap of {} LSB RMS over {} samples",
        printed_source, end.poles.max_radius, lsb(attribution.steps.front().gap.rms_lsb), n);
  }
  if (explained()) {
    return fmt::format(
        "diagnose --hw: gap {} LSB RMS explained down to 0 in {} steps; staged = model = RTL on "
        "{} of {} samples (runner: {} mismatches)",
        lsb(attribution.steps.front().gap.rms_lsb), attribution.steps.size() - 1, n, n,
        runner_mismatches);
  }
  return fmt::format(
      "diagnose --hw: NOT explained: {} LSB RMS left on {} samples after every effect; staged != "
      "model on {}, model != RTL on {} of {} samples (runner: {} mismatches)",
      lsb(end.gap.rms_lsb), end.gap.differing, staged_vs_model, model_vs_rtl, n, runner_mismatches);
}

void print_hw_diagnosis(const HwDiagnosis& d, std::ostream& out) {
  out << fmt::format(
      "flange diagnose --hw: {}, stimulus {}, {} samples{}, seed {}\n", d.coeffs, d.stimulus,
      d.real.size(),
      d.diverged_at ? fmt::format(" of {} (then the real diverged)", d.requested_samples) : "",
      d.seed);
  if (d.mode == "rtl") {
    out << fmt::format(
        "gap = Verilated RTL - model in output LSB (Q1.{}); effects added greedily, the one "
        "leaving the least gap first\n",
        d.sample_width - 1);
  } else {
    out << fmt::format(
        "gap = filter with the printed coefficients ({}) - model, in output LSB (Q1.{}), both in "
        "double precision\n",
        d.printed_source, d.sample_width - 1);
  }
  out << table_text(d) << d.final_line() << "\n";
}

void write_hw_diagnosis(const HwDiagnosis& d, const fs::path& dir) {
  fs::create_directories(dir);
  const auto write = [&dir](const std::string& name, const std::string& text) {
    std::ofstream file(dir / name, std::ios::binary);
    file << text;
    if (!file) throw std::runtime_error("cannot write " + (dir / name).string());
  };
  write("hw_diagnosis.json", to_json(d).dump(1) + "\n");
  plot_steps(d, dir);
  plot_traces(d, dir);
  std::string html =
      "<!DOCTYPE html>\n<html><head><meta charset='utf-8'><title>flange diagnose --hw: " +
      coeffs::html_escape(d.coeffs) +
      "</title>\n<style>body{font-family:sans-serif;max-width:1100px;margin:auto}"
      "pre{background:#f4f4f4;padding:8px}</style></head><body>\n"
      "<h1>flange diagnose --hw</h1>\n<p>The gap between the float design and the hardware, "
      "explained by adding the fixed-point effects of docs/fixed_point.md to the float model one "
      "at a time, the one that leaves the least gap first.</p>\n<pre>";
  std::ostringstream table;
  print_hw_diagnosis(d, table);
  html += coeffs::html_escape(table.str());
  html +=
      "</pre>\n<h2>Gap after each step</h2><p>RMS and largest absolute gap in output LSB, "
      "logarithmic; a gap of zero is drawn at 1e-4.</p><img src='gap_steps.svg'>\n"
      "<h2>Traces</h2><p>The float design's output and the real one, and the gap left after each "
      "step (first 2000 samples).</p><img src='traces.svg'>\n</body></html>\n";
  write("hw_diagnosis.html", html);
}

}  // namespace flange::diagnose
