// SPDX-License-Identifier: MIT
#include "design_outputs.h"

#include "gnuplot_runner.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <sstream>
#include <stdexcept>

namespace flange::coeffs {

namespace {

nlohmann::ordered_json complex_list(const std::vector<Complex>& values) {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const Complex& value : values) list.push_back({value.real(), value.imag()});
  return list;
}

// JSON has no NaN or infinity; an optional figure that is absent or not finite is null.
nlohmann::ordered_json finite_or_null(const std::optional<double>& value) {
  if (!value || !std::isfinite(*value)) return nullptr;
  return *value;
}

std::string hex_word(std::int64_t word, int bits) {
  const auto mask = bits >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << bits) - 1;
  const int digits = (bits + 3) / 4;
  return fmt::format("{:0{}x}", static_cast<std::uint64_t>(word) & mask, digits);
}

double magnitude_db(Complex response) {
  // Clamped for plotting only: the exact zeros at Nyquist would be -infinity.
  return std::max(-300.0, 20.0 * std::log10(std::abs(response)));
}

// A figure for display: rounding noise below the printed precision shows as 0, not -0.
double shown(double value, double precision) {
  return std::abs(value) < precision / 2.0 ? 0.0 : value;
}

void write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream file(path, std::ios::binary);
  if (!file) throw std::runtime_error("cannot write " + path.string());
  file << text;
  if (!file) throw std::runtime_error("cannot write " + path.string());
}


// Per channel of a set per channel: its float design and what its rounding did.
nlohmann::ordered_json channel_sets_json(const DesignRecord& record) {
  nlohmann::ordered_json sets = nlohmann::ordered_json::array();
  for (const RecordChannelSet& set : record.channel_sets) {
    nlohmann::ordered_json sos = nlohmann::ordered_json::array();
    for (const Section& section : set.design.cascade.sections) {
      sos.push_back(
          {section.b[0], section.b[1], section.b[2], section.a[0], section.a[1], section.a[2]});
    }
    nlohmann::ordered_json values = nlohmann::ordered_json::array();
    for (const QuantizedSection& section : set.quantized.sections) {
      values.push_back({{"b", section.b}, {"a", section.a}, {"e", section.error_feedback}});
    }
    sets.push_back({{"fc_hz", set.design.fc_hz},
                    {"sos", sos},
                    {"leftover_gain", set.design.cascade.leftover_gain},
                    {"section_values", values},
                    {"max_pole_radius", set.analysis.max_pole_radius},
                    {"stable", set.analysis.stable},
                    {"dc_gain_error_db", set.analysis.dc_gain_error_db},
                    {"passband_deviation_db", finite_or_null(set.analysis.passband_deviation_db)}});
  }
  return sets;
}

}  // namespace

nlohmann::ordered_json filter_json(const DesignRecord& record) {
  const FloatDesign& design = record.design;
  const QuantizedFilter& q = record.quantized;
  const QuantizedAnalysis& analysis = record.analysis;
  nlohmann::ordered_json json;
  json["generated_by"] = record.generated_by;
  json["name"] = record.name;
  json["fs_hz"] = design.fs_hz;
  json["order"] = design.order;
  json["fc_hz"] = design.fc_hz;
  if (design.spec) {
    json["spec"] = {{"fp_hz", design.spec->fp_hz},
                    {"fa_hz", design.spec->fa_hz},
                    {"ap_db", design.spec->ap_db},
                    {"aa_db", design.spec->aa_db}};
  } else {
    json["spec"] = nullptr;
  }
  json["b"] = design.b;
  json["a"] = design.a;
  json["zeros"] = complex_list(design.zpk.zeros);
  json["poles"] = complex_list(design.zpk.poles);
  json["gain"] = design.zpk.gain;
  nlohmann::ordered_json sos = nlohmann::ordered_json::array();
  for (const Section& section : design.cascade.sections) {
    sos.push_back(
        {section.b[0], section.b[1], section.b[2], section.a[0], section.a[1], section.a[2]});
  }
  json["sos"] = sos;
  json["leftover_gain"] = design.cascade.leftover_gain;

  nlohmann::ordered_json quantized;
  quantized["structure"] = structure_name(q.structure);
  quantized["coef_bits"] = q.widths.coef_bits;
  quantized["coef_frac_bits"] = q.coef_frac_bits;
  quantized["feedback_shift"] = q.feedback_shift;
  quantized["split_shift"] = q.split_shift;
  quantized["data_bits"] = q.widths.data_bits;
  quantized["acc_bits"] = q.widths.acc_bits;
  quantized["acc_bits_needed"] = q.acc_bits_needed;
  quantized["sections"] = q.section_count;
  quantized["section_order"] = q.section_order;
  quantized["rom_depth"] = q.words.size();
  quantized["rom_order"] =
      "per section: lo words of b[0..M] and -a[1..M], hi words of b[0..M] and -a[1..M], "
      "error feedback E[1..M]";
  quantized["words"] = all_words(record);
  quantized["channels"] = record.channels;
  quantized["coef_sets"] = record.coef_sets();
  nlohmann::ordered_json values = nlohmann::ordered_json::array();
  for (const QuantizedSection& section : q.sections) {
    values.push_back({{"b", section.b}, {"a", section.a}, {"e", section.error_feedback}});
  }
  quantized["section_values"] = values;
  quantized["leftover_gain"] = q.leftover_gain;
  quantized["poles"] = complex_list(analysis.poles);
  quantized["max_pole_radius"] = analysis.max_pole_radius;
  quantized["stable"] = analysis.stable;
  quantized["dc_gain_error_db"] = analysis.dc_gain_error_db;
  quantized["passband_loss_db"] = finite_or_null(analysis.passband_loss_db);
  quantized["passband_peak_db"] = finite_or_null(analysis.passband_peak_db);
  quantized["stopband_atten_db"] = finite_or_null(analysis.stopband_atten_db);
  quantized["passband_deviation_db"] = finite_or_null(analysis.passband_deviation_db);
  quantized["meets_spec"] = analysis.meets_spec;
  json["quantized"] = quantized;
  if (!record.channel_sets.empty()) json["channel_sets"] = channel_sets_json(record);
  return json;
}

std::vector<std::int64_t> all_words(const DesignRecord& record) {
  if (record.channel_sets.empty()) return record.quantized.words;
  std::vector<std::int64_t> words;
  for (const RecordChannelSet& set : record.channel_sets) {
    words.insert(words.end(), set.quantized.words.begin(), set.quantized.words.end());
  }
  return words;
}

std::string rom_image(const DesignRecord& record) {
  const QuantizedFilter& q = record.quantized;
  std::ostringstream text;
  text << "// generated by: " << record.generated_by << "\n";
  text << fmt::format(
      "// {} sections x (lo b[0..{m}], lo -a[1..{m}], hi b[0..{m}], hi -a[1..{m}], E[1..{m}]); "
      "{}-bit two's complement; c = (hi + lo 2^-{}) 2^-{}\n",
      q.section_count, q.widths.coef_bits, q.split_shift, q.coef_frac_bits,
      fmt::arg("m", q.section_order));
  if (record.channel_sets.empty()) {
    for (std::int64_t word : q.words) text << hex_word(word, q.widths.coef_bits) << "\n";
    return text.str();
  }
  for (std::size_t c = 0; c < record.channel_sets.size(); ++c) {
    const RecordChannelSet& set = record.channel_sets[c];
    text << fmt::format("// channel {}: fc = {:.6g} Hz\n", c, set.design.fc_hz);
    for (std::int64_t word : set.quantized.words) {
      text << hex_word(word, q.widths.coef_bits) << "\n";
    }
  }
  return text.str();
}

int channel_width(int channels) {
  int width = 1;
  while ((1 << width) < channels) ++width;
  return width;
}

std::string params_package(const DesignRecord& record) {
  const QuantizedFilter& q = record.quantized;
  std::ostringstream text;
  text << "// generated by: " << record.generated_by << "\n";
  text << "// SPDX-License-Identifier: MIT\n";
  text << fmt::format(
      "// Parameters of the '{}' filter: {} Butterworth low-pass, order {}, "
      "fc = {:.6g} Hz at fs = {:.6g} Hz.\n",
      record.name, structure_name(q.structure), record.design.order, record.design.fc_hz,
      record.design.fs_hz);
  text << "// Formats: docs/fixed_point.md. Coefficients: coeffs.mem beside this file.\n";
  text << "package iir_coeffs_pkg;\n";
  auto param = [&text](const char* name, long long value, const char* why) {
    text << fmt::format("  localparam int {} = {};  // {}\n", name, value, why);
  };
  param("FilterOrder", record.design.order, "order of the whole filter");
  param("NumSections", q.section_count, "sections run one after another on one MAC");
  param("SectionOrder", q.section_order, "order of every section");
  param("SampleWidth", q.widths.data_bits, "samples are Q1.(SampleWidth-1)");
  param("CoefWidth", q.widths.coef_bits, "ROM word width");
  param("CoefFracBits", q.coef_frac_bits, "F: fractional bits of the hi words");
  param("FeedbackShift", q.feedback_shift, "s: extra fraction bits of every signal in the core");
  param("SplitShift", q.split_shift, "L = CoefWidth - 1: lo words weigh 2^-L of a hi word");
  param("AccWidth", q.widths.acc_bits, "accumulator width");
  param("RomDepth", static_cast<long long>(q.words.size()), "NumSections * (5 * SectionOrder + 2)");
  param("NumChannels", record.channels, "independent channels sharing the MAC");
  param("CoefSets", record.coef_sets(), "coefficient sets in the ROM: 1 (shared) or NumChannels");
  param("ChannelWidth", channel_width(record.channels), "max(1, clog2(NumChannels))");
  text << "endpackage\n";
  return text.str();
}

void write_response_plot(const DesignRecord& record, const std::filesystem::path& svg_path) {
  const FloatDesign& design = record.design;
  const double nyquist = design.fs_hz / 2.0;
  const double f_low =
      std::min(design.fc_hz, design.spec ? design.spec->fp_hz : design.fc_hz) / 100.0;
  std::ostringstream script;
  script << "set terminal svg size 900,700 dynamic font 'sans,12' background '#ffffff'\n";
  script << "set output '" << svg_path.string() << "'\n";
  script << "$response << EOD\n";
  constexpr int kPoints = 800;
  for (int i = 0; i <= kPoints; ++i) {
    const double f = f_low * std::pow(nyquist / f_low, static_cast<double>(i) / kPoints);
    const double omega = 2.0 * std::numbers::pi * f / design.fs_hz;
    script << fmt::format("{:.9g} {:.9g} {:.9g}\n", f, magnitude_db(float_response(design, omega)),
                          magnitude_db(quantized_response(record.quantized, omega)));
  }
  script << "EOD\n";
  double floor_db = -120.0;
  if (design.spec) floor_db = std::min(floor_db, -design.spec->aa_db - 40.0);
  script << "set multiplot layout 2,1 title '" << record.name << ": "
         << structure_name(record.quantized.structure) << ", order " << design.order << ", "
         << record.quantized.widths.coef_bits << "-bit coefficients'\n";
  script << "set grid\nset key bottom left\nset logscale x\n";
  script << fmt::format("set xrange [{:.9g}:{:.9g}]\nset yrange [{:.6g}:5]\n", f_low, nyquist,
                        floor_db);
  script << "set xlabel 'frequency (Hz)'\nset ylabel 'magnitude (dB)'\n";
  std::string mask;
  if (design.spec) {
    const LowpassSpec& spec = *design.spec;
    // The mask, shaded where the response must not go: below -ap up to fp, above -aa from fa.
    script << fmt::format(
        "set object 1 rect from {:.9g},{:.6g} to {:.9g},{:.6g} fc rgb '#d0d0d0' fs solid 0.5 "
        "noborder behind\n",
        f_low, floor_db, spec.fp_hz, -spec.ap_db);
    script << fmt::format(
        "set object 2 rect from {:.9g},{:.6g} to {:.9g},5 fc rgb '#d0d0d0' fs solid 0.5 "
        "noborder behind\n",
        spec.fa_hz, -spec.aa_db, nyquist);
    mask = ", NaN with boxes fc rgb '#d0d0d0' fs solid 0.5 title 'spec mask (forbidden)'";
  }
  script << "plot $response using 1:2 with lines lw 2 lc rgb '#1f77b4' title 'float', "
            "$response using 1:3 with lines lw 1.5 dt 2 lc rgb '#d62728' title 'quantised'"
         << mask << "\n";
  script << "unset object 1\nunset object 2\nunset logscale x\n";
  const double detail_hi = 1.5 * std::max(design.fc_hz, design.spec ? design.spec->fp_hz : 0.0);
  script << fmt::format("set xrange [0:{:.9g}]\nset yrange [-4:0.5]\n",
                        std::min(detail_hi, nyquist));
  script << "set title 'passband detail'\n";
  if (design.spec) {
    script << fmt::format(
        "set arrow 1 from 0,{0:.6g} to {1:.9g},{0:.6g} nohead lc rgb '#606060' dt 3\n",
        -design.spec->ap_db, design.spec->fp_hz);
  }
  script << "plot $response using 1:2 with lines lw 2 lc rgb '#1f77b4' title 'float', "
            "$response using 1:3 with lines lw 1.5 dt 2 lc rgb '#d62728' title 'quantised'\n";
  script << "unset multiplot\n";

  run_gnuplot(script.str(), svg_path.string());
  // Name the command that made the plot in the SVG's description (an XML comment cannot hold
  // the "--" of the options).
  std::ifstream in(svg_path, std::ios::binary);
  std::string svg((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  in.close();
  const std::size_t svg_tag = svg.find("<svg");
  const std::size_t tag_end =
      svg_tag == std::string::npos ? std::string::npos : svg.find('>', svg_tag);
  if (tag_end == std::string::npos)
    throw std::runtime_error("gnuplot wrote no SVG to " + svg_path.string());
  svg.insert(tag_end + 1, "\n<desc>generated by: " + record.generated_by + "</desc>");
  write_text(svg_path, svg);
}

std::string design_report(const DesignRecord& record) {
  const FloatDesign& design = record.design;
  const QuantizedFilter& q = record.quantized;
  const QuantizedAnalysis& analysis = record.analysis;
  std::ostringstream text;
  text << fmt::format("{}: Butterworth low-pass, order {}, fc = {:.6g} Hz, fs = {:.6g} Hz\n",
                      record.name, design.order, design.fc_hz, design.fs_hz);
  if (design.spec) {
    const LowpassSpec& spec = *design.spec;
    text << fmt::format(
        "  spec: fp = {:.6g} Hz (ap = {:.6g} dB), fa = {:.6g} Hz (aa = {:.6g} dB)\n", spec.fp_hz,
        spec.ap_db, spec.fa_hz, spec.aa_db);
  }
  text << fmt::format("  float b = [{:.4g}]\n  float a = [{:.4g}]\n", fmt::join(design.b, " "),
                      fmt::join(design.a, " "));
  text << fmt::format("  structure: {}, {} section(s) of order {}, {} MACs/sample\n",
                      structure_name(q.structure), q.section_count, q.section_order,
                      q.words.size());
  text << fmt::format(
      "  words: {}-bit coefficients split in two (hi Q.{}, lo 2^-{} finer), signals with {} extra "
      "fractional bits, {}-bit samples, {}-bit accumulator ({} needed)\n",
      q.widths.coef_bits, q.coef_frac_bits, q.split_shift, q.feedback_shift, q.widths.data_bits,
      q.widths.acc_bits, q.acc_bits_needed);
  double float_radius = 0.0;
  for (const Complex& pole : design.zpk.poles)
    float_radius = std::max(float_radius, std::abs(pole));
  text << fmt::format("  poles: max |z| = {:.6f} float, {:.6f} quantised ({} on or outside)\n",
                      float_radius, analysis.max_pole_radius, analysis.poles_outside);
  if (std::isfinite(analysis.dc_gain_error_db)) {
    text << fmt::format("  DC gain error: {:+.5f} dB\n", shown(analysis.dc_gain_error_db, 1e-5));
  }
  if (analysis.passband_loss_db) {
    text << fmt::format("  passband over 0-{:.6g} Hz: loss up to {:.4f} dB, gain up to {:.4f} dB\n",
                        design.spec->fp_hz, shown(*analysis.passband_loss_db, 1e-4),
                        shown(*analysis.passband_peak_db, 1e-4));
  }
  if (analysis.passband_deviation_db) {
    text << fmt::format("  response below fc: within {:.4f} dB of the float design\n",
                        *analysis.passband_deviation_db);
  }
  if (analysis.stopband_atten_db) {
    text << fmt::format("  stopband attenuation over {:.6g}-{:.6g} Hz: {:.2f} dB\n",
                        design.spec->fa_hz, design.fs_hz / 2.0, *analysis.stopband_atten_db);
  }
  if (std::abs(q.leftover_gain - 1.0) > 1e-12) {
    text << fmt::format("  leftover gain for the host: {:.9g}\n", q.leftover_gain);
  }
  if (record.channels > 1) {
    text << fmt::format("  channels: {} sharing one MAC, {}\n", record.channels,
                        record.channel_sets.empty() ? "one coefficient set for all"
                                                    : "a coefficient set per channel");
  }
  for (std::size_t c = 0; c < record.channel_sets.size(); ++c) {
    const RecordChannelSet& set = record.channel_sets[c];
    text << fmt::format("    channel {}: fc = {:.6g} Hz, max |z| = {:.6f}", c, set.design.fc_hz,
                        set.analysis.max_pole_radius);
    if (set.analysis.passband_deviation_db) {
      text << fmt::format(", within {:.4f} dB of its float design below fc",
                          *set.analysis.passband_deviation_db);
    }
    text << "\n";
  }
  text << "  verdict: "
       << (analysis.rejection.empty()
               ? std::string(design.spec ? "stable, meets the spec"
                                         : "stable, follows the float design")
               : "REJECTED: " + analysis.rejection)
       << "\n";
  return text.str();
}

void write_design(const DesignRecord& record, const std::filesystem::path& out_dir,
                  bool with_plot) {
  std::filesystem::create_directories(out_dir);
  write_text(out_dir / kFilterJsonFile, filter_json(record).dump(1) + "\n");
  write_text(out_dir / kRomImageFile, rom_image(record));
  write_text(out_dir / kPackageFile, params_package(record));
  if (with_plot) write_response_plot(record, out_dir / kPlotFile);
}

}  // namespace flange::coeffs
