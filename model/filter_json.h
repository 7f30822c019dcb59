// SPDX-License-Identifier: MIT
// Reads a coefficient set's filter.json (written by `flange design`) into what the bit-accurate
// model and the double-precision reference need. Every error is one line naming file and field.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace flange::model {

// A filter.json that cannot be read, is not JSON, or has a missing or out-of-range field.
class FilterJsonError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The fixed-point side of a set (`quantized.*`, docs/fixed_point.md). Names follow the package
// parameters of iir_coeffs_pkg.sv.
struct CoreConfig {
  std::string name;        // filter name, for reports
  int filter_order = 0;    // FilterOrder, 1 <= filter_order <= num_sections * section_order
  int num_sections = 0;    // NumSections (K), >= 1
  int section_order = 0;   // SectionOrder (M), >= 1
  int sample_width = 0;    // SampleWidth (D), 2..32
  int coef_width = 0;      // CoefWidth (C), 2..32
  int coef_frac_bits = 0;  // CoefFracBits (F), 1 <= F <= D + s (rounding constant 2^(F-1))
  int feedback_shift = 0;  // FeedbackShift (s) >= 0: the history's extra fractional bits
  int acc_width = 0;       // AccWidth (P), F + D + s <= P <= 64, D + s + C <= P, F + L <= P
  // Channels sharing the core (NumChannels, 1 to kMaxCoreChannels) and coefficient sets in the ROM
  // (CoefSets: 1, shared by every channel, or num_channels, set c for channel c).
  int num_channels = 1;
  int coef_sets = 1;
  // ROM words in ROM order, each a signed C-bit integer; coef_sets sets of rom_depth() words one
  // after another. Per section (docs/fixed_point.md): lo words W_b[0..M] and W_a[1..M] (of b and
  // -a, in [0, 2^L)), hi words H_b[0..M] and H_a[1..M], error-feedback words E[1..M].
  std::vector<std::int64_t> rom;

  // L: the lo words' shift, C - 1 (17 for the DSP48E1's P >>> 17).
  int split_shift() const { return coef_width - 1; }
  int terms() const { return 5 * section_order + 2; }
  // Offsets of a section's words within its terms() words.
  int lo_b(int i) const { return i; }                          // W_b[i], i = 0..M
  int lo_a(int j) const { return section_order + j; }          // W_a[j], j = 1..M
  int hi_b(int i) const { return 2 * section_order + 1 + i; }  // H_b[i]
  int hi_a(int j) const { return 3 * section_order + 1 + j; }  // H_a[j]
  int err(int j) const { return 4 * section_order + 1 + j; }   // E[j]
  int rom_depth() const { return num_sections * terms(); }  // words of one set
  // Section k's coefficients of channel c's set as the core computes them:
  // b[0..M] and a[0..M] (a[0] = 1) from the split words, (H + W 2^-L) 2^-F, and E[1..M].
  std::vector<double> b_values(int k, int channel = 0) const;
  std::vector<double> a_values(int k, int channel = 0) const;
  std::vector<std::int64_t> error_feedback(int k, int channel = 0) const;
  // The first word of channel c's set.
  const std::int64_t* channel_words(int channel) const {
    return rom.data() + (coef_sets == 1 ? 0 : channel * rom_depth());
  }
  // Channel c alone: one channel, its own set (what the channel computes, as a one-channel core).
  CoreConfig channel_config(int channel) const;
};

// Sticky flags of every channel fit one 32-bit mask (model::Pins).
inline constexpr int kMaxCoreChannels = 32;

// The float side of the same design: what the quantised core approximates.
struct FloatDesign {
  std::string name;
  double fs_hz = 0.0;                      // > 0
  std::optional<double> fc_hz;             // 3 dB cut-off, 0 < fc < fs / 2, when recorded
  std::vector<std::array<double, 6>> sos;  // rows b0 b1 b2 a0 a1 a2, a0 != 0
  std::vector<double> b, a;                // whole transfer function, a[0] != 0
  double leftover_gain = 1.0;              // applied by the host after the core
};

// Throws FilterJsonError; checks every rule of docs/fixed_point.md that the core relies on.
CoreConfig load_core_config(const std::filesystem::path& filter_json);
FloatDesign load_float_design(const std::filesystem::path& filter_json);
// Channel c's float design: that of its own set (`channel_sets[c]`, written by
// `flange design --channel-fc`), or the one design of a set shared by every channel.
FloatDesign load_float_design(const std::filesystem::path& filter_json, int channel);

// Group delay at DC in samples of the design's sections: sum n c_n / sum c_n of each numerator
// minus its denominator's, summed (what the host uses to align a filtered trace with its input).
double dc_group_delay_samples(const FloatDesign& design);

// Throws std::invalid_argument (one line naming the field) when `config` breaks the contract.
void validate_core_config(const CoreConfig& config);

}  // namespace flange::model
