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
      return "first rounding: y_ext = acc >>> Fa";
    case FixedPointEffect::kOutputRounding:
      return "second rounding: section output to D bits";
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
  return {config.sample_width, config.feedback_shift, config.coef_frac_bits, config.acc_width};
}

std::vector<SectionCoefficients> float_sections(const CoreConfig& config,
                                                const FloatDesign& design) {
  std::vector<SectionCoefficients> sections;
  // A cascade of biquads comes from the sos rows (as the generator quantises it), one section of
  // the whole order from b/a (df1).
  if (config.section_order == 2 &&
      design.sos.size() == static_cast<std::size_t>(config.num_sections)) {
    for (const auto& row : design.sos) {
      const double a0 = row[3];
      sections.push_back(
          {{row[0] / a0, row[1] / a0, row[2] / a0}, {1.0, row[4] / a0, row[5] / a0}});
    }
    return sections;
  }
  const auto m = static_cast<std::size_t>(config.section_order);
  if (config.num_sections == 1 && design.b.size() == m + 1 && design.a.size() == m + 1) {
    const double a0 = design.a[0];
    SectionCoefficients s;
    for (double v : design.b) s.b.push_back(v / a0);
    for (double v : design.a) s.a.push_back(v / a0);
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
  const int m = config.section_order;
  for (int k = 0; k < config.num_sections; ++k) {
    SectionCoefficients s;
    s.a.push_back(1.0);
    for (int i = 0; i < config.terms(); ++i) {
      const auto word =
          static_cast<double>(config.rom[static_cast<std::size_t>(k * config.terms() + i)]);
      if (i <= m) {
        s.b.push_back(std::ldexp(word, -config.num_frac_bits));
      } else {
        s.a.push_back(-std::ldexp(word, -config.coef_frac_bits));
      }
    }
    sections.push_back(std::move(s));
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
          s->a[0] != 1.0 || s->b.size() > s->a.size()) {
        throw std::invalid_argument(fmt::format(
            "StagedFixedPoint: section {}: b and a must have the same shape in both sets, a[0] = 1",
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
      format.coef_frac_bits < 1 || format.acc_width > 64 ||
      format.acc_width < format.coef_frac_bits + format.sample_width) {
    throw std::invalid_argument(fmt::format(
        "StagedFixedPoint: format D = {}, s = {}, Fa = {}, P = {} out of range",
        format.sample_width, format.feedback_shift, format.coef_frac_bits, format.acc_width));
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
  x_.clear();
  y_ext_.clear();
  for (const SectionCoefficients& s : coefficients_) {
    x_.emplace_back(s.b.size(), 0.0L);
    y_ext_.emplace_back(s.a.size(), 0.0L);
  }
}

double StagedFixedPoint::step(double x) {
  const bool feedback_rounding = effects_.has(FixedPointEffect::kFeedbackRounding);
  const bool output_rounding = effects_.has(FixedPointEffect::kOutputRounding);
  const bool wrap = effects_.has(FixedPointEffect::kAccumulatorWrap);
  const bool saturation = effects_.has(FixedPointEffect::kSaturation);
  const int s = format_.feedback_shift;
  const long double sample_max = std::ldexp(1.0L, format_.sample_width - 1) - 1.0L;
  const long double sample_min = -sample_max - 1.0L;
  const long double ext_max = std::ldexp(sample_max + 1.0L, s) - 1.0L;
  const long double ext_min = std::ldexp(sample_min, s);
  // The accumulator seen >>> Fa spans 2^(P-Fa) y_ext LSB.
  const long double span = std::ldexp(1.0L, format_.acc_width - format_.coef_frac_bits);

  long double u = effects_.has(FixedPointEffect::kInputRounding)
                      ? static_cast<long double>(round_input_sample(x, format_.sample_width))
                      : static_cast<long double>(x);
  for (std::size_t k = 0; k < coefficients_.size(); ++k) {
    const SectionCoefficients& c = coefficients_[k];
    std::vector<long double>& xs = x_[k];
    std::vector<long double>& ys = y_ext_[k];
    std::rotate(xs.rbegin(), xs.rbegin() + 1, xs.rend());
    xs[0] = u;
    long double acc = 0.0L;
    for (std::size_t i = 0; i < c.b.size(); ++i) acc += static_cast<long double>(c.b[i]) * xs[i];
    acc = std::ldexp(acc, s);
    // ys[0] is the previous output until this section's new one is stored.
    std::rotate(ys.rbegin(), ys.rbegin() + 1, ys.rend());
    for (std::size_t j = 1; j < c.a.size(); ++j) acc -= static_cast<long double>(c.a[j]) * ys[j];

    long double t = acc;
    if (feedback_rounding) t += 0.5L;  // the rounding constant 2^(Fa-1), preloaded
    if (wrap) t -= span * std::floor((t + span / 2) / span);
    if (feedback_rounding) t = std::floor(t);
    if (saturation) t = std::clamp(t, ext_min, ext_max);
    ys[0] = t;

    long double y = std::ldexp(t, -s);
    if (output_rounding) y = std::floor(y + 0.5L);
    if (saturation) y = std::clamp(y, sample_min, sample_max);
    u = y;
  }
  return static_cast<double>(u);
}

}  // namespace flange::model
