// SPDX-License-Identifier: MIT
#include "staged_fixed_point.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace flange::model {

std::string effect_name(FixedPointEffect effect) {
  switch (effect) {
    case FixedPointEffect::kCoefficients:
      return "coefficients";
    case FixedPointEffect::kInputRounding:
      return "input_rounding";
    case FixedPointEffect::kFeedbackRounding:
      return "feedback_rounding";
    case FixedPointEffect::kOutputRounding:
      return "output_rounding";
    case FixedPointEffect::kAccumulatorWrap:
      return "accumulator_wrap";
    case FixedPointEffect::kSaturation:
      return "saturation";
  }
  return "unknown";
}

std::string effect_description(FixedPointEffect effect) {
  switch (effect) {
    case FixedPointEffect::kCoefficients:
      return "coefficient quantisation (ROM words)";
    case FixedPointEffect::kInputRounding:
      return "input rounded to the sample format";
    case FixedPointEffect::kFeedbackRounding:
      return "rounding inside the core: lo >>> L, y_ext = acc >>> F, error fed back";
    case FixedPointEffect::kOutputRounding:
      return "output rounding: sample_o to D bits";
    case FixedPointEffect::kAccumulatorWrap:
      return "P-bit accumulator wrap";
    case FixedPointEffect::kSaturation:
      return "saturation of y_ext and of the output";
  }
  return "unknown";
}

EffectSet EffectSet::all() {
  EffectSet set;
  for (FixedPointEffect e : kAllFixedPointEffects) set = set.with(e);
  return set;
}

EffectSet EffectSet::with(FixedPointEffect e) const {
  EffectSet set = *this;
  set.bits_ |= bit(e);
  return set;
}

std::vector<FixedPointEffect> EffectSet::list() const {
  std::vector<FixedPointEffect> effects;
  for (FixedPointEffect e : kAllFixedPointEffects) {
    if (has(e)) effects.push_back(e);
  }
  return effects;
}

StagedFormat staged_format(const CoreConfig& config) {
  return {config.sample_width, config.feedback_shift, config.coef_frac_bits, config.acc_width,
          config.split_shift()};
}

std::vector<std::int64_t> error_feedback_words(const std::vector<double>& a) {
  std::vector<std::int64_t> e;
  for (std::size_t j = 1; j < a.size(); ++j) e.push_back(std::llround(-a[j]));
  return e;
}

std::vector<SectionCoefficients> float_sections(const CoreConfig& config,
                                                const FloatDesign& design) {
  std::vector<SectionCoefficients> sections;
  // A cascade of biquads (or of first-order sections, the test-only cascades) comes from the sos
  // rows (as the generator quantises it), one section of the whole order from b/a (df1).
  const bool cascade = config.section_order == 2 || config.num_sections > 1;
  if (cascade && design.sos.size() == static_cast<std::size_t>(config.num_sections)) {
    for (const auto& row : design.sos) {
      const double a0 = row[3];
      if (config.section_order == 1) {
        sections.push_back({{row[0] / a0, row[1] / a0}, {1.0, row[4] / a0}, {}});
      } else {
        sections.push_back(
            {{row[0] / a0, row[1] / a0, row[2] / a0}, {1.0, row[4] / a0, row[5] / a0}, {}});
      }
    }
    for (SectionCoefficients& section : sections) section.e = error_feedback_words(section.a);
    return sections;
  }
  const auto m = static_cast<std::size_t>(config.section_order);
  if (config.num_sections == 1 && design.b.size() == m + 1 && design.a.size() == m + 1) {
    const double a0 = design.a[0];
    SectionCoefficients s;
    for (double v : design.b) s.b.push_back(v / a0);
    for (double v : design.a) s.a.push_back(v / a0);
    s.e = error_feedback_words(s.a);
    sections.push_back(std::move(s));
    return sections;
  }
  throw std::invalid_argument(fmt::format(
      "{}: the float design ({} sos rows, b/a of order {}) does not have the shape of the core "
      "({} sections of order {})",
      design.name, design.sos.size(), design.a.empty() ? 0 : design.a.size() - 1,
      config.num_sections, config.section_order));
}

std::vector<SectionCoefficients> rom_sections(const CoreConfig& config) {
  std::vector<SectionCoefficients> sections;
  for (int k = 0; k < config.num_sections; ++k) {
    sections.push_back({config.b_values(k), config.a_values(k), config.error_feedback(k)});
  }
  return sections;
}

std::int32_t round_input_sample(double x, int sample_width) {
  if (std::isnan(x)) throw std::invalid_argument("round_input_sample: the input is NaN");
  const double hi = std::ldexp(1.0, sample_width - 1) - 1.0;
  return static_cast<std::int32_t>(std::clamp(std::floor(x + 0.5), -hi - 1.0, hi));
}

namespace {

void check_shape(const std::vector<SectionCoefficients>& exact,
                 const std::vector<SectionCoefficients>& quantised) {
  if (exact.empty() || exact.size() != quantised.size()) {
    throw std::invalid_argument(fmt::format(
        "StagedFixedPoint: {} exact and {} quantised sections (need the same number, >= 1)",
        exact.size(), quantised.size()));
  }
  for (std::size_t k = 0; k < exact.size(); ++k) {
    for (const auto* s : {&exact[k], &quantised[k]}) {
      if (s->b.size() != exact[k].b.size() || s->a.size() != exact[k].a.size() || s->a.empty() ||
          s->a[0] != 1.0 || s->b.size() > s->a.size() || s->e.size() + 1 != s->a.size()) {
        throw std::invalid_argument(fmt::format(
            "StagedFixedPoint: section {}: b, a and e must have the same shape in both sets, a[0] = "
            "1, one e per a[j], j >= 1",
            k));
      }
    }
  }
}

}  // namespace

StagedFixedPoint::StagedFixedPoint(const StagedFormat& format,
                                   std::vector<SectionCoefficients> exact,
                                   std::vector<SectionCoefficients> quantised, EffectSet effects)
    : format_(format), effects_(effects) {
  check_shape(exact, quantised);
  if (format.sample_width < 2 || format.sample_width > 32 || format.feedback_shift < 0 ||
      format.coef_frac_bits < 1 || format.acc_width > 64 || format.split_shift < 1 ||
      format.acc_width < format.coef_frac_bits + format.sample_width + format.feedback_shift ||
      format.acc_width < format.coef_frac_bits + format.split_shift) {
    throw std::invalid_argument(fmt::format(
        "StagedFixedPoint: format D = {}, s = {}, F = {}, P = {}, L = {} out of range",
        format.sample_width, format.feedback_shift, format.coef_frac_bits, format.acc_width,
        format.split_shift));
  }
  coefficients_ =
      effects.has(FixedPointEffect::kCoefficients) ? std::move(quantised) : std::move(exact);
  reset();
}

StagedFixedPoint::StagedFixedPoint(const CoreConfig& config, const FloatDesign& design,
                                   EffectSet effects)
    : StagedFixedPoint(staged_format(config), float_sections(config, design), rom_sections(config),
                       effects) {}

void StagedFixedPoint::reset() {
  u_.clear();
  y_ext_.clear();
  err_.clear();
  for (const SectionCoefficients& s : coefficients_) {
    u_.emplace_back(s.b.size(), 0.0L);
    y_ext_.emplace_back(s.a.size(), 0.0L);
    err_.emplace_back(s.a.size(), 0.0L);
  }
}

namespace {

// A P-bit two's complement register holding `t` (in its LSB): t wrapped to [-2^(P-1), 2^(P-1)).
long double wrapped(long double t, int width) {
  const long double span = std::ldexp(1.0L, width);
  return t - span * std::floor((t + span / 2) / span);
}

}  // namespace

double StagedFixedPoint::step(double x) {
  const bool quantised = effects_.has(FixedPointEffect::kCoefficients);
  const bool rounding = effects_.has(FixedPointEffect::kFeedbackRounding);
  const bool output_rounding = effects_.has(FixedPointEffect::kOutputRounding);
  const bool wrap = effects_.has(FixedPointEffect::kAccumulatorWrap);
  const bool saturation = effects_.has(FixedPointEffect::kSaturation);
  const int s = format_.feedback_shift;
  const int f = format_.coef_frac_bits;
  const int split = format_.split_shift;
  const long double sample_max = std::ldexp(1.0L, format_.sample_width - 1) - 1.0L;
  const long double sample_min = -sample_max - 1.0L;
  const long double ext_max = std::ldexp(sample_max + 1.0L, s) - 1.0L;
  const long double ext_min = std::ldexp(sample_min, s);
  const long double half = std::ldexp(1.0L, f - 1);  // the rounding constant, accumulator LSB

  const long double input = effects_.has(FixedPointEffect::kInputRounding)
                                ? static_cast<long double>(round_input_sample(x, format_.sample_width))
                                : static_cast<long double>(x);
  long double u = std::ldexp(input, s);  // y_ext units from here on
  for (std::size_t k = 0; k < coefficients_.size(); ++k) {
    const SectionCoefficients& c = coefficients_[k];
    std::vector<long double>& us = u_[k];
    std::vector<long double>& ys = y_ext_[k];
    std::vector<long double>& es = err_[k];
    std::rotate(us.rbegin(), us.rbegin() + 1, us.rend());
    us[0] = u;
    // ys[0] and es[0] are the previous sample's until this section's new ones are stored.
    std::rotate(ys.rbegin(), ys.rbegin() + 1, ys.rend());
    std::rotate(es.rbegin(), es.rbegin() + 1, es.rend());
    // In accumulator LSB (2^-F of a y_ext LSB). Quantised coefficients are split as in the ROM,
    // c 2^(F+L) = H 2^L + W, and the lo phase (the W terms) is shifted down by L; exact ones
    // are summed whole.
    long double lo = rounding ? std::ldexp(half, split) : 0.0L;  // 2^L accumulator LSB units
    long double hi = 0.0L;
    const auto add = [&](long double coefficient, long double operand) {
      if (!quantised) {
        hi += std::ldexp(coefficient * operand, f);
        return;
      }
      const long double whole = std::ldexp(coefficient, f + split);  // an integer
      const long double upper = std::floor(std::ldexp(whole, -split));
      lo += (whole - std::ldexp(upper, split)) * operand;
      hi += upper * operand;
    };
    for (std::size_t i = 0; i < c.b.size(); ++i) add(c.b[i], us[i]);
    for (std::size_t j = 1; j < c.a.size(); ++j) add(-c.a[j], ys[j]);
    if (wrap) lo = wrapped(lo, format_.acc_width);
    long double acc = std::ldexp(lo, -split);
    if (rounding) acc = std::floor(acc);
    acc += hi;
    for (std::size_t j = 1; j < c.a.size(); ++j) {
      acc += static_cast<long double>(c.e[j - 1]) * es[j];
    }
    if (wrap) acc = wrapped(acc, format_.acc_width);

    long double t = std::ldexp(acc, -f);
    if (rounding) {
      t = std::floor(t);
      es[0] = acc - std::ldexp(t, f) - half;  // what the rounding dropped, fed back
    } else {
      es[0] = 0.0L;
    }
    if (saturation) t = std::clamp(t, ext_min, ext_max);
    ys[0] = t;
    u = t;
  }
  long double y = std::ldexp(u, -s);
  if (output_rounding) y = std::floor(y + 0.5L);
  if (saturation) y = std::clamp(y, sample_min, sample_max);
  return static_cast<double>(y);
}

}  // namespace flange::model
