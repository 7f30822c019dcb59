// SPDX-License-Identifier: MIT
// A "partly fixed-point" filter: the float design with the fixed-point effects of
// docs/fixed_point.md switched on one at a time, for attributing the gap between the float design
// and the hardware (`flange diagnose --hw`). With every effect on it is IirCore word for word; with
// every effect off it is ReferenceFilter (within double rounding).
//
// Units: samples in and out are in LSB of the D-bit sample format (Q1.(D-1) times 2^(D-1)), as
// reals; the section's feedback history y_ext is in LSB of its (D+s)-bit format, as in the
// contract. Per section and sample, in y_ext units, with v the exact sum
//   v = 2^s sum_i b[i] x_k[n-i] - sum_j a[j] y_ext_k[n-j],
// the effects act as follows (in this order; an effect switched off leaves the value alone):
//   feedback rounding  t = v + 1/2 (the accumulator's rounding constant) ... t = floor(t)
//   accumulator wrap   t wraps to [-2^(P-1-Fa), 2^(P-1-Fa)), the P-bit accumulator seen >>> Fa
//   saturation         y_ext = clamp(t, -2^(D-1+s), 2^(D-1+s) - 1)
//   output rounding    y = floor(y_ext 2^-s + 1/2)          (the second rounding, to D bits)
//   saturation         y = clamp(y, -2^(D-1), 2^(D-1) - 1)  (y goes on to the next section)
// Input rounding rounds the filter input to a D-bit word: floor(x + 1/2), clipped to the range
// (the ADC). Coefficient quantisation replaces the exact coefficients by the quantised ones (the
// ROM words b = B 2^-Fb, a = -A 2^-Fa for a coefficient set).
// Arithmetic is long double (64-bit significand on x86-64): with quantised coefficients, rounded
// data and legal samples every term and partial sum is an integer multiple of 2^-Fa below
// 2^(P-1-Fa) in magnitude, so the sum is exact for any P <= 64, as the model's integers are.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "filter_json.h"

namespace flange::model {

static_assert(std::numeric_limits<long double>::digits >= 64,
              "StagedFixedPoint needs a 64-bit significand to be exact with 64-bit accumulators");

enum class FixedPointEffect {
  kCoefficients,      // coefficient quantisation: the ROM words instead of the float design
  kInputRounding,     // the input rounded (and clipped) to a D-bit word
  kFeedbackRounding,  // the first rounding: y_ext = floor(acc / 2^Fa + 1/2)
  kOutputRounding,    // the second rounding: each section's D-bit output from y_ext
  kAccumulatorWrap,   // the P-bit two's complement accumulator
  kSaturation,        // y_ext clipped to D + s bits, each section's output to D bits
};
inline constexpr std::array<FixedPointEffect, 6> kAllFixedPointEffects = {
    FixedPointEffect::kCoefficients,     FixedPointEffect::kInputRounding,
    FixedPointEffect::kFeedbackRounding, FixedPointEffect::kOutputRounding,
    FixedPointEffect::kAccumulatorWrap,  FixedPointEffect::kSaturation};

std::string effect_name(FixedPointEffect effect);         // e.g. "feedback_rounding"
std::string effect_description(FixedPointEffect effect);  // e.g. "first rounding (y_ext)"

// A set of effects switched on.
class EffectSet {
 public:
  static EffectSet none() { return EffectSet{}; }
  static EffectSet all();
  bool has(FixedPointEffect e) const { return (bits_ & bit(e)) != 0; }
  EffectSet with(FixedPointEffect e) const;
  std::vector<FixedPointEffect> list() const;  // in kAllFixedPointEffects order
  bool operator==(const EffectSet&) const = default;

 private:
  static unsigned bit(FixedPointEffect e) { return 1u << static_cast<unsigned>(e); }
  unsigned bits_ = 0;
};

// One section's coefficients, a[0] = 1: y = sum b[i] x[n-i] - sum_{j>=1} a[j] y[n-j].
struct SectionCoefficients {
  std::vector<double> b, a;
};

// The formats the effects need (docs/fixed_point.md symbols).
struct StagedFormat {
  int sample_width = 16;   // D, 2..32
  int feedback_shift = 0;  // s, 0..25 - D
  int coef_frac_bits = 1;  // Fa, >= 1
  int acc_width = 48;      // P, Fa + D <= P <= 64
};
StagedFormat staged_format(const CoreConfig& config);

// The float design in the structure of `config`: the normalised sos rows for a cascade of order-2
// sections, the whole b/a for one section (df1). Throws std::invalid_argument when the design
// does not have the shape of the config.
std::vector<SectionCoefficients> float_sections(const CoreConfig& config,
                                                const FloatDesign& design);
// The ROM words of `config` as values: b = B 2^-Fb, a[j] = -A 2^-Fa (exact in double).
std::vector<SectionCoefficients> rom_sections(const CoreConfig& config);

// The D-bit word the core receives for an input of `x` LSB: floor(x + 1/2), clipped to
// [-2^(D-1), 2^(D-1) - 1]. NaN is refused (std::invalid_argument).
std::int32_t round_input_sample(double x, int sample_width);

class StagedFixedPoint {
 public:
  // `exact` and `quantised` must have the same shape (sections, b and a lengths, a[0] = 1).
  // Throws std::invalid_argument otherwise or when `format` is out of range.
  StagedFixedPoint(const StagedFormat& format, std::vector<SectionCoefficients> exact,
                   std::vector<SectionCoefficients> quantised, EffectSet effects);
  // The float design and the ROM of one coefficient set.
  StagedFixedPoint(const CoreConfig& config, const FloatDesign& design, EffectSet effects);

  // One input, in LSB of the D-bit input (any finite real; rounded only with kInputRounding).
  // Returns the output in LSB, without the design's leftover gain (as the core).
  double step(double x);
  void reset();

  EffectSet effects() const { return effects_; }
  // The coefficients in use: quantised with kCoefficients, exact otherwise.
  const std::vector<SectionCoefficients>& coefficients() const { return coefficients_; }

 private:
  StagedFormat format_;
  EffectSet effects_;
  std::vector<SectionCoefficients> coefficients_;
  std::vector<std::vector<long double>> x_, y_ext_;  // per section, newest first
};

}  // namespace flange::model
