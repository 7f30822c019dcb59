// SPDX-License-Identifier: MIT
#include "quantize.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>

#include "design_error.h"

namespace flange::coeffs {

namespace {

__extension__ using Int128 = __int128;

double largest_magnitude(const std::vector<double>& values) {
  double largest = 0.0;
  for (double value : values) largest = std::max(largest, std::abs(value));
  return largest;
}

// Smallest number of integer bits I such that every value, rounded with C - 1 - I fractional
// bits, fits a signed C-bit word. nullopt when all values are zero.
std::optional<int> integer_bits(const std::vector<double>& values, int coef_bits) {
  const double largest = largest_magnitude(values);
  if (largest == 0.0) return std::nullopt;
  if (!std::isfinite(largest)) {
    throw DesignRejected("a coefficient is not finite; the float design is degenerate");
  }
  int bits = static_cast<int>(std::ceil(std::log2(largest)));
  const double word_max = std::ldexp(1.0, coef_bits - 1) - 1.0;
  while (std::round(std::ldexp(largest, coef_bits - 1 - bits)) > word_max) ++bits;
  return bits;
}

std::int64_t round_to_word(double value, int frac_bits) {
  return std::llround(std::ldexp(value, frac_bits));  // to nearest, ties away from zero
}

// Float coefficients of the structure, per section: numerator b[0..M], denominator a[0..M].
struct FloatSections {
  std::vector<std::vector<double>> b;
  std::vector<std::vector<double>> a;
  double leftover_gain = 1.0;
};

FloatSections float_sections(const FloatDesign& design, Structure structure) {
  FloatSections sections;
  if (structure == Structure::kDf1) {
    sections.b.push_back(design.b);
    sections.a.push_back(design.a);
    return sections;
  }
  for (const Section& section : design.cascade.sections) {
    sections.b.emplace_back(section.b.begin(), section.b.end());
    sections.a.emplace_back(section.a.begin(), section.a.end());
  }
  sections.leftover_gain = design.cascade.leftover_gain;
  return sections;
}

std::string format_number(double value) { return fmt::format("{:.6g}", value); }

// The denominators' coefficients after a[0], section after section.
std::vector<double> feedback_coefficients(const FloatSections& sections) {
  std::vector<double> feedback;
  for (std::size_t k = 0; k < sections.b.size(); ++k) {
    feedback.insert(feedback.end(), sections.a[k].begin() + 1, sections.a[k].end());
  }
  return feedback;
}

std::vector<double> all_values(const std::vector<std::vector<double>>& rows) {
  std::vector<double> values;
  for (const std::vector<double>& row : rows) values.insert(values.end(), row.begin(), row.end());
  return values;
}

// A coefficient split into its hi and lo words (docs/fixed_point.md): c = (H + W 2^-L) 2^-F,
// H = floor(c 2^F) in C bits and W in [0, 2^L). The whole word H 2^L + W is c rounded to
// F + L fractional bits, to nearest (ties away from zero).
struct SplitWord {
  std::int64_t hi = 0;
  std::int64_t lo = 0;
  std::int64_t whole = 0;
};

SplitWord split_word(double value, int frac_bits, int split) {
  SplitWord word;
  word.whole = round_to_word(value, frac_bits + split);
  word.hi = word.whole >> split;  // floor (C++20 arithmetic shift)
  word.lo = word.whole & ((std::int64_t{1} << split) - 1);
  return word;
}

// Numerator compensation: scale each section's numerator by A_q(1) / A(1), the rounded
// denominator's DC value over the exact one, so that rounding the denominator of a narrow
// filter (where A(1) is tiny) does not move the section's DC gain.
std::vector<std::vector<double>> compensated_numerators(const FloatSections& sections, int f,
                                                        int split) {
  std::vector<std::vector<double>> numerators = sections.b;
  for (std::size_t k = 0; k < sections.b.size(); ++k) {
    double exact_dc = 1.0;
    double rounded_dc = 1.0;
    for (std::size_t j = 1; j < sections.a[k].size(); ++j) {
      exact_dc += sections.a[k][j];
      rounded_dc -= std::ldexp(static_cast<double>(split_word(-sections.a[k][j], f, split).whole),
                               -(f + split));
    }
    if (exact_dc != 0.0 && rounded_dc != 0.0 &&
        std::signbit(exact_dc) == std::signbit(rounded_dc)) {
      for (double& value : numerators[k]) value *= rounded_dc / exact_dc;
    }
  }
  return numerators;
}

// F: as many fractional bits as the largest coefficient, numerator or denominator, leaves in a
// C-bit hi word, at most `max_frac_bits`; a word too narrow to leave a fractional bit rejects the
// design.
int frac_bits_for(const std::vector<double>& feedback, const std::vector<double>& feedforward,
                  const FloatDesign& design, Structure structure, int c, int max_frac_bits) {
  std::vector<double> values = feedback;
  values.insert(values.end(), feedforward.begin(), feedforward.end());
  const std::optional<int> integer = integer_bits(values, c);
  const int f = std::min(integer ? c - 1 - *integer : c - 1, max_frac_bits);
  if (f < 1) {
    throw DesignRejected(fmt::format(
        "{} of order {} needs {} integer bits for its largest coefficient ({}); {}-bit "
        "coefficients leave none for the fraction; {}",
        structure == Structure::kDf1 ? "direct form" : "second-order sections", design.order,
        integer.value_or(0), format_number(largest_magnitude(values)), c,
        structure == Structure::kDf1 ? "use --structure sos or more coefficient bits"
                                     : "use more coefficient bits"));
  }
  return f;
}

// Two's complement of P bits holds magnitudes up to 2^(P-1) - 1.
int accumulator_bits_needed(Int128 worst) {
  int needed = 1;
  while ((Int128{1} << (needed - 1)) <= worst) ++needed;
  return needed;
}

// Rounds every section's coefficients in the format already in `filter` into its words (ROM
// order: W_b[0..M], W_a[1..M], H_b[0..M], H_a[1..M], E[1..M]) and sections. Returns the worst
// case of either phase of the accumulator over the sections (docs/fixed_point.md): every operand
// is at most 2^(D-1+s) in magnitude, every error at most 2^(F-1).
Int128 round_sections(const FloatSections& sections,
                      const std::vector<std::vector<double>>& numerators, QuantizedFilter& filter) {
  const int f = filter.coef_frac_bits;
  const int split = filter.split_shift;
  const int operand_shift = filter.widths.data_bits - 1 + filter.feedback_shift;
  Int128 worst_any = 0;
  for (std::size_t k = 0; k < sections.b.size(); ++k) {
    std::vector<SplitWord> b, a;
    for (double value : numerators[k]) b.push_back(split_word(value, f, split));
    for (std::size_t j = 1; j < sections.a[k].size(); ++j) {
      a.push_back(split_word(-sections.a[k][j], f, split));  // stored negated
    }
    QuantizedSection quantized;
    Int128 lo_sum = 0, hi_sum = 0, err_sum = 0;
    for (const SplitWord& word : b) {
      filter.words.push_back(word.lo);
      lo_sum += word.lo;
      quantized.b.push_back(std::ldexp(static_cast<double>(word.whole), -(f + split)));
    }
    quantized.a.push_back(1.0);
    for (const SplitWord& word : a) {
      filter.words.push_back(word.lo);
      lo_sum += word.lo;
      quantized.a.push_back(-std::ldexp(static_cast<double>(word.whole), -(f + split)));
    }
    for (const SplitWord& word : b) {
      filter.words.push_back(word.hi);
      hi_sum += word.hi < 0 ? -word.hi : word.hi;
    }
    for (const SplitWord& word : a) {
      filter.words.push_back(word.hi);
      hi_sum += word.hi < 0 ? -word.hi : word.hi;
    }
    // Error feedback 1 - sum E[j] z^-j as close to A(z) as integers get: E[j] = round(-a[j]).
    for (std::size_t j = 1; j < sections.a[k].size(); ++j) {
      const std::int64_t e = std::llround(-sections.a[k][j]);
      filter.words.push_back(e);
      quantized.error_feedback.push_back(e);
      err_sum += e < 0 ? -e : e;
    }
    filter.sections.push_back(std::move(quantized));
    const Int128 lo_phase = (Int128{1} << (f - 1 + split)) + (lo_sum << operand_shift);
    const Int128 shifted = ((lo_sum << operand_shift) >> split) + 1;
    const Int128 hi_phase = (Int128{1} << (f - 1)) + shifted + (hi_sum << operand_shift) +
                            (err_sum << (f - 1));
    worst_any = std::max({worst_any, lo_phase, hi_phase});
  }
  return worst_any;
}

}  // namespace

std::string structure_name(Structure structure) {
  return structure == Structure::kDf1 ? "df1" : "sos";
}

QuantizedFilter quantize(const FloatDesign& design, Structure structure,
                         const HardwareWidths& widths, std::optional<int> max_feedback_shift,
                         std::optional<int> max_frac_bits) {
  const FloatSections sections = float_sections(design, structure);
  QuantizedFilter filter;
  filter.structure = structure;
  filter.widths = widths;
  filter.section_count = static_cast<int>(sections.b.size());
  filter.section_order = static_cast<int>(sections.b.front().size()) - 1;
  filter.leftover_gain = sections.leftover_gain;

  const int c = widths.coef_bits;
  filter.split_shift = c - 1;
  int shift = std::max(0, kDspAPortBits - widths.data_bits);
  if (max_feedback_shift) shift = std::clamp(*max_feedback_shift, 0, shift);
  filter.feedback_shift = shift;
  // The error word (F bits) rides the same A port as the history: F <= D + s.
  int frac_cap = widths.data_bits + shift;
  if (max_frac_bits) frac_cap = std::min(frac_cap, *max_frac_bits);

  // F from the raw coefficients, then from the compensated numerators (compensation moves them by
  // parts per million, which can cross a word boundary).
  const std::vector<double> feedback = feedback_coefficients(sections);
  int f = frac_bits_for(feedback, all_values(sections.b), design, structure, c, frac_cap);
  std::vector<std::vector<double>> numerators = compensated_numerators(sections, f, c - 1);
  const int settled = frac_bits_for(feedback, all_values(numerators), design, structure, c, f);
  if (settled != f) {
    f = settled;
    numerators = compensated_numerators(sections, f, c - 1);
  }
  filter.coef_frac_bits = f;

  const int needed = accumulator_bits_needed(round_sections(sections, numerators, filter));
  filter.acc_bits_needed = needed;
  if (needed > widths.acc_bits) {
    throw DesignRejected(fmt::format(
        "the {}-bit accumulator can overflow: the worst case of {}-bit samples times these "
        "{}-bit coefficients needs {} bits; use --acc-bits {} or more",
        widths.acc_bits, widths.data_bits, c, needed, needed));
  }
  return filter;
}

Complex float_response(const FloatDesign& design, double omega) {
  const Complex w = std::polar(1.0, -omega);  // z^-1
  Complex value(design.zpk.gain, 0.0);
  // Each root in product form stays accurate where the expanded polynomials of a narrow
  // high-order filter lose every digit.
  for (const Complex& zero : design.zpk.zeros) value *= (1.0 - zero * w);
  for (const Complex& pole : design.zpk.poles) value /= (1.0 - pole * w);
  return value;
}

Complex quantized_response(const QuantizedFilter& filter, double omega) {
  Complex value(filter.leftover_gain, 0.0);
  for (const QuantizedSection& section : filter.sections) {
    value *= eval_z_inverse(section.b, omega) / eval_z_inverse(section.a, omega);
  }
  return value;
}

namespace {

double loss_db(Complex response) { return -20.0 * std::log10(std::abs(response)); }

// Extreme of the loss over [f_lo, f_hi] (Hz) on a dense grid that includes both edges.
double extreme_loss_db(const QuantizedFilter& filter, double fs_hz, double f_lo, double f_hi,
                       bool largest) {
  constexpr int kPoints = 4096;
  double extreme =
      largest ? -std::numeric_limits<double>::infinity() : std::numeric_limits<double>::infinity();
  for (int i = 0; i <= kPoints; ++i) {
    const double f = f_lo + (f_hi - f_lo) * i / kPoints;
    const double loss = loss_db(quantized_response(filter, 2.0 * std::numbers::pi * f / fs_hz));
    extreme = largest ? std::max(extreme, loss) : std::min(extreme, loss);
  }
  return extreme;
}

std::string structure_phrase(const QuantizedFilter& filter) {
  return filter.structure == Structure::kDf1
             ? fmt::format("direct form (order {})", filter.section_order)
             : fmt::format("{} second-order section{}", filter.section_count,
                           filter.section_count == 1 ? "" : "s");
}

std::string fix_phrase(const QuantizedFilter& filter) {
  return filter.structure == Structure::kDf1 ? "use --structure sos or more coefficient bits"
                                             : "use more coefficient bits (--coef-bits)";
}

void find_poles(const QuantizedFilter& filter, QuantizedAnalysis& analysis) {
  for (const QuantizedSection& section : filter.sections) {
    for (const Complex& pole : polynomial_roots(section.a)) {
      analysis.poles.push_back(pole);
      analysis.max_pole_radius = std::max(analysis.max_pole_radius, std::abs(pole));
      if (std::abs(pole) >= 1.0) ++analysis.poles_outside;
    }
  }
}

std::string instability_rejection(const QuantizedFilter& filter,
                                  const QuantizedAnalysis& analysis) {
  return fmt::format(
      "{} with {}-bit coefficients puts {} pole{} on or outside the unit circle "
      "(max |z| = {:.4f}); {}",
      structure_phrase(filter), filter.widths.coef_bits, analysis.poles_outside,
      analysis.poles_outside == 1 ? "" : "s", analysis.max_pole_radius, fix_phrase(filter));
}

std::string passband_rejection(const LowpassSpec& spec, const QuantizedFilter& filter,
                               const AcceptanceLimits& limits, const QuantizedAnalysis& analysis) {
  return fmt::format(
      "quantised {} misses the spec: passband {} {:.4f} dB over 0-{} Hz exceeds ap = {} dB "
      "(+{} dB tolerance); {}",
      structure_phrase(filter),
      *analysis.passband_loss_db >= *analysis.passband_peak_db ? "loss" : "gain",
      std::max(*analysis.passband_loss_db, *analysis.passband_peak_db), format_number(spec.fp_hz),
      format_number(spec.ap_db), format_number(limits.spec_tolerance_db), fix_phrase(filter));
}

// The float design's smallest attenuation over [fa, fs/2], on the grid extreme_loss_db uses.
double float_stopband_atten_db(const FloatDesign& design, const LowpassSpec& spec) {
  double float_atten = std::numeric_limits<double>::infinity();
  constexpr int kPoints = 4096;
  for (int i = 0; i <= kPoints; ++i) {
    const double f = spec.fa_hz + (spec.fs_hz / 2.0 - spec.fa_hz) * i / kPoints;
    float_atten = std::min(
        float_atten, loss_db(float_response(design, 2.0 * std::numbers::pi * f / spec.fs_hz)));
  }
  return float_atten;
}

// Says whether rounding lost the attenuation or the design never had it.
std::string stopband_rejection(const FloatDesign& design, const LowpassSpec& spec,
                               const QuantizedFilter& filter, const AcceptanceLimits& limits,
                               const QuantizedAnalysis& analysis) {
  const double float_atten = float_stopband_atten_db(design, spec);
  const bool design_misses = float_atten < spec.aa_db - limits.spec_tolerance_db;
  return fmt::format(
      "quantised {} misses the spec: stopband attenuation {:.2f} dB over {}-{} Hz is below "
      "aa = {} dB; {}",
      structure_phrase(filter), *analysis.stopband_atten_db, format_number(spec.fa_hz),
      format_number(spec.fs_hz / 2.0), format_number(spec.aa_db),
      design_misses ? fmt::format("the float design itself gives only {:.2f} dB: raise "
                                  "--order or design from the spec alone",
                                  float_atten)
                    : fix_phrase(filter));
}

void judge_against_spec(const FloatDesign& design, const LowpassSpec& spec,
                        const QuantizedFilter& filter, const AcceptanceLimits& limits,
                        QuantizedAnalysis& analysis) {
  analysis.passband_loss_db = extreme_loss_db(filter, spec.fs_hz, 0.0, spec.fp_hz, true);
  analysis.passband_peak_db = -extreme_loss_db(filter, spec.fs_hz, 0.0, spec.fp_hz, false);
  analysis.stopband_atten_db =
      extreme_loss_db(filter, spec.fs_hz, spec.fa_hz, spec.fs_hz / 2.0, false);
  // The passband may deviate by ap either way: a gain bump from moved poles is as wrong as a
  // loss, and above 0 dB it eats the headroom of the sample format.
  const bool passband_ok = *analysis.passband_loss_db <= spec.ap_db + limits.spec_tolerance_db &&
                           *analysis.passband_peak_db <= spec.ap_db + limits.spec_tolerance_db;
  const bool stopband_ok = *analysis.stopband_atten_db >= spec.aa_db - limits.spec_tolerance_db;
  analysis.meets_spec = passband_ok && stopband_ok;
  if (!passband_ok) {
    analysis.rejection = passband_rejection(spec, filter, limits, analysis);
  } else if (!stopband_ok) {
    analysis.rejection = stopband_rejection(design, spec, filter, limits, analysis);
  }
}

// Largest |quantised - float| loss in dB from DC to the cut-off.
double deviation_from_float_db(const FloatDesign& design, const QuantizedFilter& filter) {
  double deviation = 0.0;
  constexpr int kPoints = 4096;
  for (int i = 0; i <= kPoints; ++i) {
    const double omega = 2.0 * std::numbers::pi * design.fc_hz / design.fs_hz * i / kPoints;
    deviation = std::max(deviation, std::abs(loss_db(quantized_response(filter, omega)) -
                                             loss_db(float_response(design, omega))));
  }
  if (!std::isfinite(deviation)) deviation = std::numeric_limits<double>::max();
  return deviation;
}

// Without a mask, the quantised response must follow the float one up to the cut-off.
void judge_against_float(const FloatDesign& design, const QuantizedFilter& filter,
                         const AcceptanceLimits& limits, QuantizedAnalysis& analysis) {
  const double deviation = deviation_from_float_db(design, filter);
  analysis.passband_deviation_db = deviation;
  const bool dc_ok = std::abs(analysis.dc_gain_error_db) <= limits.max_dc_error_db;
  const bool shape_ok = deviation <= limits.max_passband_deviation_db;
  analysis.meets_spec = dc_ok && shape_ok;
  if (!dc_ok) {
    analysis.rejection =
        fmt::format("quantised {} has a DC gain error of {:.4f} dB, beyond the {} dB allowed; {}",
                    structure_phrase(filter), analysis.dc_gain_error_db,
                    format_number(limits.max_dc_error_db), fix_phrase(filter));
  } else if (!shape_ok) {
    analysis.rejection = fmt::format(
        "quantised {} departs from the float response by {:.3f} dB below fc = {} Hz, beyond the "
        "{} dB allowed; {}",
        structure_phrase(filter), deviation, format_number(design.fc_hz),
        format_number(limits.max_passband_deviation_db), fix_phrase(filter));
  }
}

}  // namespace

QuantizedAnalysis analyse(const FloatDesign& design, const QuantizedFilter& filter,
                          const AcceptanceLimits& limits) {
  QuantizedAnalysis analysis;
  find_poles(filter, analysis);
  analysis.stable = analysis.poles_outside == 0;
  const double float_dc = std::abs(float_response(design, 0.0));
  const double quantized_dc = std::abs(quantized_response(filter, 0.0));
  analysis.dc_gain_error_db = 20.0 * std::log10(quantized_dc / float_dc);

  if (!analysis.stable) {
    analysis.rejection = instability_rejection(filter, analysis);
  } else if (design.spec) {
    judge_against_spec(design, *design.spec, filter, limits, analysis);
  } else {
    judge_against_float(design, filter, limits, analysis);
  }
  return analysis;
}

}  // namespace flange::coeffs
