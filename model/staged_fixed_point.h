// SPDX-License-Identifier: MIT
// A "partly fixed-point" filter: the float design with the fixed-point effects of
// docs/fixed_point.md switched on one at a time, for attributing the gap between the float design
// and the hardware (`flange diagnose --hw`). With every effect on it is IirCore word for word; with
// every effect off it is ReferenceFilter (within double rounding).
//
// Units: samples in and out are in LSB of the D-bit sample format (Q1.(D-1) times 2^(D-1)), as
// reals; every signal inside (each section's input u and output history y_ext) is in LSB of the
// (D+s)-bit format, as in the contract, and the sums in accumulator LSB (2^-F of that). Per
// section and sample (an effect switched off leaves the value alone):
//   coefficients       the ROM's split words instead of the float design: each coefficient
//                      c 2^(F+L) = H 2^L + W, and the W terms form the lo phase
//   feedback rounding  the lo phase starts at 2^(F-1+L) and is floored after >>> L; y_ext =
//                      floor(acc 2^-F), and the error acc - y_ext 2^F - 2^(F-1) is fed back
//                      through E[j] (round(-a[j]) for the float design)
//   accumulator wrap   the lo phase and acc wrap to P-bit two's complement
//   saturation         y_ext = clamp(y_ext, -2^(D-1+s), 2^(D-1+s) - 1), and the output below
// The filter output is the last y_ext in sample LSB: with output rounding floor(y 2^-s + 1/2),
// with saturation clipped to [-2^(D-1), 2^(D-1) - 1]. Input rounding rounds the filter input to
// a D-bit word: floor(x + 1/2), clipped to the range (the ADC).
// Arithmetic is long double (64-bit significand on x86-64): with quantised coefficients, rounded
// data and legal samples every term and partial sum is an integer below 2^63, so the sums are
// exact, as the model's integers are.
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
  kFeedbackRounding,  // rounding inside: lo >>> L, y_ext = acc >>> F, the error fed back
  kOutputRounding,    // sample_o rounded to D bits from the last y_ext
  kAccumulatorWrap,   // the P-bit two's complement accumulator
  kSaturation,        // y_ext clipped to D + s bits, sample_o to D bits
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

// One section's coefficients, a[0] = 1: y = sum b[i] x[n-i] - sum_{j>=1} a[j] y[n-j], and its
// error-feedback words e[j-1] = E[j].
struct SectionCoefficients {
  std::vector<double> b, a;
  std::vector<std::int64_t> e;
};
// E[j] = round(-a[j]), j >= 1: the generator's error feedback for denominator a.
std::vector<std::int64_t> error_feedback_words(const std::vector<double>& a);

// The formats the effects need (docs/fixed_point.md symbols).
struct StagedFormat {
  int sample_width = 16;   // D, 2..32
  int feedback_shift = 0;  // s, 0..25 - D
  int coef_frac_bits = 1;  // F, >= 1
  int acc_width = 48;      // P, F + D + s <= P <= 64, F + L <= P
  int split_shift = 17;    // L, >= 1
};
StagedFormat staged_format(const CoreConfig& config);

// The float design in the structure of `config`: the normalised sos rows for a cascade of order-2
// sections, the whole b/a for one section (df1). Throws std::invalid_argument when the design
// does not have the shape of the config.
std::vector<SectionCoefficients> float_sections(const CoreConfig& config,
                                                const FloatDesign& design);
// The ROM words of `config` as values, (H + W 2^-L) 2^-F (exact in double), and its E words.
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
  std::vector<std::vector<long double>> u_, y_ext_, err_;  // per section, newest first
};

}  // namespace flange::model
