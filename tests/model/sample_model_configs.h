// SPDX-License-Identifier: MIT
// Hand-made contract-v2 configurations for the sample model's tests (iir_sample_model_test.cpp,
// iir_sample_bank_test.cpp): float sections quantised the way docs/fixed_point.md describes
// (c = (H + W 2^-L) 2^-F, W in [0, 2^L), E[j] = round(-a[j])), so that they behave like the
// generator's sets without depending on the checked-in files.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "filter_json.h"

namespace flange::model::testing {

struct FloatSection {
  std::vector<double> b, a;  // b[0..M], a[0..M] with a[0] = 1
};

struct Widths {
  int d, c, f, s, p;  // SampleWidth, CoefWidth, CoefFracBits, FeedbackShift, AccWidth
};

// The section's words in ROM order (W_b, W_a, H_b, H_a, E), with b scaled to unit DC gain when
// `unit_dc` (the generator spreads the gain over the sections the same way).
inline std::vector<std::int64_t> quantize_section(FloatSection section, const Widths& w,
                                                  bool unit_dc = true) {
  const int m = static_cast<int>(section.a.size()) - 1;
  if (unit_dc) {
    double sum_b = 0.0, sum_a = 0.0;
    for (int i = 0; i <= m; ++i) sum_b += section.b[static_cast<std::size_t>(i)];
    for (int i = 0; i <= m; ++i) sum_a += section.a[static_cast<std::size_t>(i)];
    if (std::abs(sum_b) > 1e-9) {  // a high-pass has no DC gain to scale
      for (double& b : section.b) b *= sum_a / sum_b;
    }
  }
  const int split = w.c - 1;
  const std::int64_t hi_max = (std::int64_t{1} << (w.c - 1)) - 1;
  std::vector<std::int64_t> lo_b, lo_a, hi_b, hi_a, err;
  const auto split_word = [&](double c, std::vector<std::int64_t>& lo,
                              std::vector<std::int64_t>& hi) {
    const std::int64_t v = std::llround(std::ldexp(c, w.f + split));
    const std::int64_t h = v >> split;  // floor
    if (h > hi_max || h < -hi_max - 1) throw std::range_error("coefficient does not fit C bits");
    hi.push_back(h);
    lo.push_back(v - h * (std::int64_t{1} << split));
  };
  for (int i = 0; i <= m; ++i) split_word(section.b[static_cast<std::size_t>(i)], lo_b, hi_b);
  for (int j = 1; j <= m; ++j) {
    const double minus_a = -section.a[static_cast<std::size_t>(j)];
    split_word(minus_a, lo_a, hi_a);
    err.push_back(std::clamp<std::int64_t>(std::llround(minus_a), -hi_max - 1, hi_max));
  }
  std::vector<std::int64_t> words;
  for (const auto* part : {&lo_b, &lo_a, &hi_b, &hi_a, &err}) {
    words.insert(words.end(), part->begin(), part->end());
  }
  return words;
}

inline CoreConfig make_config(const std::string& name, const std::vector<FloatSection>& sections,
                              const Widths& w) {
  CoreConfig c;
  c.name = name;
  c.num_sections = static_cast<int>(sections.size());
  c.section_order = static_cast<int>(sections.front().a.size()) - 1;
  c.filter_order = c.num_sections * c.section_order;
  c.sample_width = w.d;
  c.coef_width = w.c;
  c.coef_frac_bits = w.f;
  c.feedback_shift = w.s;
  c.acc_width = w.p;
  for (const FloatSection& s : sections) {
    const std::vector<std::int64_t> words = quantize_section(s, w);
    c.rom.insert(c.rom.end(), words.begin(), words.end());
  }
  validate_core_config(c);
  return c;
}

// scipy.signal designs (sos rows b0 b1 b2 1 a1 a2).
inline std::vector<FloatSection> butter8_low_001() {  // butter(8, 0.01): poles near z = 1
  return {{{1, 2, 1}, {1, -1.939269633591658, 0.9402270185020654}},
          {{1, 2, 1}, {1, -1.9481335385151675, 0.9490952993868512}},
          {{1, 2, 1}, {1, -1.9647269019487286, 0.9656968546857874}},
          {{1, 2, 1}, {1, -1.9868379069766875, 0.987818775546285}}};
}
inline std::vector<FloatSection> butter6_low_01() {  // butter(6, 0.1)
  return {{{1, 2, 1}, {1, -1.4648681939512453, 0.5402535694278697}},
          {{1, 2, 1}, {1, -1.5610180758007182, 0.6413515380575631}},
          {{1, 2, 1}, {1, -1.7612492291001696, 0.8518870318675977}}};
}
inline std::vector<FloatSection> cheby1_4_02() {  // cheby1(4, 1 dB, 0.2): peaking sections
  return {{{1, 2, 1}, {1, -1.5547851795965146, 0.6492954381365807}},
          {{1, 2, 1}, {1, -1.4995544968104397, 0.8482186817166955}}};
}
inline std::vector<FloatSection> butter5_df_02() {  // butter(5, 0.2) as one fifth-order section
  return {{{0.0012825810789606855, 0.006412905394803428, 0.012825810789606856, 0.012825810789606856,
            0.006412905394803428, 0.0012825810789606855},
           {1.0, -2.9754221097456828, 3.806018119320411, -2.5452528683304663, 0.8811300754378364,
            -0.1254306221553556}}};
}
inline std::vector<FloatSection> first_order_pair() {  // butter(1, 0.05), then butter(1, 0.3, high)
  return {{{1, 1}, {1.0, -0.8540806854634666}},
          {{0.6624598481164532, -0.6624598481164532}, {1.0, -0.32491969623290634}}};
}

struct NamedConfig {
  std::string name;  // CamelCase, for test names
  CoreConfig config;
};

// Shapes of the generator's sets: 16-bit samples, 18-bit words, P = 48, and the edges D + s = 25
// and M = 1, 5.
inline std::vector<NamedConfig> hand_made_configs() {
  return {
      {"Butter8Narrow", make_config("butter8_narrow", butter8_low_001(), {16, 18, 16, 7, 48})},
      {"Butter6", make_config("butter6", butter6_low_01(), {16, 18, 16, 3, 48})},
      {"Cheby4", make_config("cheby4", cheby1_4_02(), {16, 18, 16, 4, 48})},
      {"Butter5Df", make_config("butter5_df", butter5_df_02(), {16, 18, 15, 8, 48})},
      {"FirstOrderPair", make_config("first_order_pair", first_order_pair(), {12, 16, 14, 2, 40})},
      {"Wide25", make_config("wide25", butter6_low_01(), {24, 18, 16, 1, 48})},
      {"NoShift", make_config("no_shift", cheby1_4_02(), {16, 18, 16, 0, 48})},
  };
}

}  // namespace flange::model::testing
