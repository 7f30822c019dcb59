// SPDX-License-Identifier: MIT
// How close the bit-accurate core comes to the float design it was quantised from (SNR, with the
// thresholds stated per set), and what it does under zero input (limit cycles, dead bands).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>
#include <random>
#include <string>

#include "fidelity.h"
#include "filter_json.h"
#include "iir_core.h"
#include "reference_filter.h"

namespace flange::model {
namespace {

struct SetCase {
  std::string folder;        // relative to the source tree
  double min_sine_snr_db;    // passband sine, fc / 4, half scale
  double min_random_snr_db;  // uniform random, half scale
};

// Measured figures are in docs/core.md. Every set built from a 6 Hz / 0.5 Hz-class design clears
// 60 dB (sine) and 50 dB (random). The vehicle filter (fc / fs = 0.0026) does not: with every
// section's output, and so its feedback state, rounded to 16 bits, each biquad has a dead band of
// 0.5 / (1 + a1 + a2) ~ 1900 LSB (docs/core.md, "Limit cycles"). Its thresholds only guard
// against getting worse; the fix belongs to the fixed-point contract.
const std::vector<SetCase> kSets = {
    {"coeffs/measurement_sos", 60.0, 50.0},
    {"coeffs/measurement_df1", 60.0, 50.0},
    {"coeffs/vehicle_sos", 5.0, -10.0},
    {"tests/data/coeffs/sos_order1", 60.0, 50.0},
    {"tests/data/coeffs/sos_order2", 60.0, 50.0},
    {"tests/data/coeffs/sos_order3", 60.0, 50.0},
    {"tests/data/coeffs/sos_order4", 60.0, 50.0},
    {"tests/data/coeffs/sos_order8", 60.0, 50.0},
    {"tests/data/coeffs/sos_order12", 60.0, 50.0},
};

std::filesystem::path json_of(const SetCase& c) {
  return std::filesystem::path(FLANGE_SOURCE_DIR) / c.folder / "filter.json";
}

// SNR of the core against the float design for `x` (LSB), skipping the first `skip` outputs.
double core_snr_db(const SetCase& c, const std::vector<std::int32_t>& x, std::size_t skip) {
  const CoreConfig config = load_core_config(json_of(c));
  const FloatDesign design = load_float_design(json_of(c));
  IirCore core(config);
  ReferenceFilter ref(design);
  const double scale = std::ldexp(1.0, config.sample_width - 1);
  std::vector<double> r, t;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double y_ref = ref.step(x[i] / scale);
    const double y = core.step(x[i]).sample * design.leftover_gain / scale;
    if (i >= skip) {
      r.push_back(y_ref);
      t.push_back(y);
    }
  }
  return snr_db(r, t);
}

TEST(IirCoreFidelity, PassbandSineSnr) {
  for (const SetCase& c : kSets) {
    const FloatDesign design = load_float_design(json_of(c));
    const double f = design.fc_hz.value() / 4;
    std::vector<std::int32_t> x;
    for (std::size_t i = 0; i < 40000; ++i) {
      x.push_back(static_cast<std::int32_t>(
          std::lround(0.5 * 32768 *
                      std::sin(2 * std::numbers::pi * f * static_cast<double>(i) / design.fs_hz))));
    }
    const double snr = core_snr_db(c, x, 15000);
    std::cout << fmt::format(
        "[snr] {}: passband sine (fc/4, 0.5 FS) {:.1f} dB (threshold {:.0f})\n", c.folder, snr,
        c.min_sine_snr_db);
    EXPECT_GE(snr, c.min_sine_snr_db) << c.folder;
  }
}

TEST(IirCoreFidelity, UniformRandomSnr) {
  for (const SetCase& c : kSets) {
    std::mt19937_64 rng(1);
    std::uniform_int_distribution<std::int32_t> u(-16384, 16383);
    std::vector<std::int32_t> x(40000);
    for (auto& v : x) v = u(rng);
    const double snr = core_snr_db(c, x, 15000);
    std::cout << fmt::format("[snr] {}: uniform random (0.5 FS) {:.1f} dB (threshold {:.0f})\n",
                             c.folder, snr, c.min_random_snr_db);
    EXPECT_GE(snr, c.min_random_snr_db) << c.folder;
  }
}

TEST(IirCoreFidelity, ZeroInputTailWithinTheRoundingBound) {
  // After a half-scale negative step and a long run of zeros, whatever is left (limit cycle or
  // dead band) is made of rounding errors only, so it must stay inside limit_cycle_bound_lsb.
  for (const SetCase& c : kSets) {
    const CoreConfig config = load_core_config(json_of(c));
    IirCore core(config);
    std::vector<std::int32_t> y;
    for (int i = 0; i < 4000; ++i) y.push_back(core.step(-16384).sample);
    for (int i = 0; i < 40000; ++i) y.push_back(core.step(0).sample);
    const LimitCycle lc = find_limit_cycle(y, 4000, 2000);
    const double bound = limit_cycle_bound_lsb(config);
    std::cout << fmt::format("[zero input] {}: {}; rounding bound {:.1f} LSB\n", c.folder,
                             lc.describe(), bound);
    EXPECT_NE(lc.period, 0u) << c.folder << ": not settled";
    EXPECT_LE(lc.amplitude, bound) << c.folder;
  }
}

TEST(IirCoreFidelity, LimitCycleBoundOfAFirstOrderSection) {
  // y_ext = round(0.5 y_ext1) with s = 2: 1/A has l1 norm 2, so the feedback rounding (1/8 LSB)
  // circulates to at most 1/4 LSB (the dead band of y_ext in
  // IirCoreModel.ExtendedFeedbackAndDeadBand), plus 1/2 LSB for the output rounding: 0.75 LSB.
  CoreConfig c;
  c.filter_order = 1;
  c.num_sections = 1;
  c.section_order = 1;
  c.sample_width = 8;
  c.coef_width = 8;
  c.num_frac_bits = 4;
  c.coef_frac_bits = 2;
  c.feedback_shift = 2;
  c.acc_width = 32;
  c.rom = {16, 0, 2};
  EXPECT_NEAR(limit_cycle_bound_lsb(c), 0.75, 1e-9);
}

TEST(IirCoreFidelity, FindsPeriodAndDeadBand) {
  const std::vector<std::int32_t> cycle = {9, 9, 3, -4, 3, -4, 3, -4, 3, -4, 3, -4};
  const LimitCycle lc = find_limit_cycle(cycle, 8, 4);
  EXPECT_EQ(lc.period, 2u);
  EXPECT_EQ(lc.amplitude, 4);
  EXPECT_EQ(lc.settled_after, 2u);
  const LimitCycle zero = find_limit_cycle({5, 1, 0, 0, 0, 0}, 4, 2);
  EXPECT_TRUE(zero.decays_to_zero);
  EXPECT_EQ(zero.settled_after, 2u);
  const LimitCycle none = find_limit_cycle({1, 2, 3, 4, 5, 6, 7, 8}, 8, 3);
  EXPECT_EQ(none.period, 0u);
  EXPECT_NEAR(snr_db({1.0, -1.0}, {1.0, -0.9}), 10 * std::log10(2.0 / 0.01), 1e-9);
}

}  // namespace
}  // namespace flange::model
