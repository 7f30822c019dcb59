// SPDX-License-Identifier: MIT
// Quantisation of a float design for the hardware (docs/fixed_point.md) and the analysis of
// what the rounding did: poles, passband loss, stopband attenuation, DC gain.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "float_design.h"

namespace flange::coeffs {

enum class Structure {
  kDf1,  // one direct-form-I section of the full order (the thesis's architecture)
  kSos,  // a cascade of direct-form-I biquads
};
std::string structure_name(Structure structure);  // "df1" or "sos"

inline constexpr int kDspAPortBits = 25;  // DSP48E1 A port: feedback samples shift into it

// Word widths of the hardware. Valid ranges are where each is declared.
struct HardwareWidths {
  int coef_bits = 18;  // [4, 32]; 18 is the DSP48E1 B port
  int data_bits = 16;  // [4, 24]; samples are Q1.(data_bits-1)
  int acc_bits = 48;   // [16, 64]; 48 is the DSP48E1 P register
};
inline constexpr int kMinCoefBits = 4, kMaxCoefBits = 32;
inline constexpr int kMinDataBits = 4, kMaxDataBits = 24;
inline constexpr int kMinAccBits = 16, kMaxAccBits = 64;

// The value of one quantised section (a[0] = 1), as the hardware computes it.
struct QuantizedSection {
  std::vector<double> b;
  std::vector<double> a;
  std::vector<std::int64_t> error_feedback;  // E[1..M]
};

struct QuantizedFilter {
  Structure structure = Structure::kSos;
  HardwareWidths widths;
  int section_count = 0;
  int section_order = 0;            // 2 for sos, N for df1
  int coef_frac_bits = 0;           // F: fractional bits of the hi words
  int feedback_shift = 0;           // s: extra fractional bits of every signal inside the core
  int split_shift = 0;              // L = C - 1: the lo words' shift
  int acc_bits_needed = 0;          // worst case over the sections and phases, sign included
  // ROM order, per section: W_b[0..M], W_a[1..M], H_b[0..M], H_a[1..M], E[1..M].
  std::vector<std::int64_t> words;
  std::vector<QuantizedSection> sections;
  double leftover_gain = 1.0;  // applied by the host
};

// Picks the format (docs/fixed_point.md) and splits every coefficient into hi and lo words.
// `max_feedback_shift` caps s below the A port's own limit (25 - D) and `max_frac_bits` caps F:
// channels that share one core need one format. Throws DesignRejected when a coefficient needs
// more integer bits than the word has, or the accumulator could overflow.
QuantizedFilter quantize(const FloatDesign& design, Structure structure,
                         const HardwareWidths& widths,
                         std::optional<int> max_feedback_shift = std::nullopt,
                         std::optional<int> max_frac_bits = std::nullopt);

// Frequency response of the float design (from its zeros, poles and gain) and of the
// quantised filter (from its sections, times its leftover gain); omega in rad/sample.
Complex float_response(const FloatDesign& design, double omega);
Complex quantized_response(const QuantizedFilter& filter, double omega);

// When a quantised filter is accepted.
struct AcceptanceLimits {
  double spec_tolerance_db = 0.01;  // slack on ap and aa for the rounding of a spec met exactly
  double max_dc_error_db = 0.1;     // DC gain error allowed when no spec was given
  double max_passband_deviation_db = 0.5;  // |quantised - float| in dB over [0, fc], no spec
};

struct QuantizedAnalysis {
  std::vector<Complex> poles;
  double max_pole_radius = 0.0;
  int poles_outside = 0;  // poles with |z| >= 1
  bool stable = false;
  double dc_gain_error_db = 0.0;                // quantised over float, at DC
  std::optional<double> passband_loss_db;       // largest loss over [0, fp] (spec only)
  std::optional<double> passband_peak_db;       // largest gain over [0, fp] (spec only)
  std::optional<double> stopband_atten_db;      // smallest attenuation over [fa, fs/2] (spec only)
  std::optional<double> passband_deviation_db;  // largest |quantised - float| dB to fc (no spec)
  bool meets_spec = false;                      // the spec, or the DC limit without one
  std::string rejection;                        // one line naming cause and fix; empty if accepted
};

QuantizedAnalysis analyse(const FloatDesign& design, const QuantizedFilter& filter,
                          const AcceptanceLimits& limits);

}  // namespace flange::coeffs
