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
  std::string folder;         // relative to the source tree
  double min_sine_snr_db;     // passband sine, fc / 4, half scale
  double min_random_snr_db;   // uniform random, half scale
  std::int32_t max_tail_lsb;  // largest |y| once the zero-input tail has settled
};

// Floors about 1 dB below the figures measured under contract v2 (docs/core.md; the runs are
// deterministic), and the zero-input tails as measured: every set decays to 0. The half-scale
// sine sits at the output rounding's floor (97.1 - 5 = 92.1 dB) for every set; the vehicle
// filter's random figure is lower because a 0.26 Hz low-pass passes little of white noise. Under
// the first contract the vehicle filter had 40.0 / 33.3 dB and a 13 LSB dead band (its 18-bit
// coefficients), and fed back at 16 bits before that 9.7 dB, -3.8 dB and 5435 LSB.
const std::vector<SetCase> kSets = {
    {"coeffs/measurement_sos", 91.0, 82.0, 0},
    {"coeffs/measurement_df1", 91.0, 82.0, 0},
    {"coeffs/vehicle_sos", 91.0, 66.5, 0},
    {"tests/data/coeffs/sos_order1", 90.0, 82.5, 0},
    {"tests/data/coeffs/sos_order2", 90.5, 81.5, 0},
    {"tests/data/coeffs/sos_order3", 91.0, 81.5, 0},
    {"tests/data/coeffs/sos_order4", 91.0, 81.5, 0},
    {"tests/data/coeffs/sos_order8", 90.5, 81.5, 0},
    {"tests/data/coeffs/sos_order12", 92.5, 81.0, 0},
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

// A passband sine, fc / 4, at `level` of full scale, 40000 samples.
std::vector<std::int32_t> passband_sine(const FloatDesign& design, double level) {
  const double f = design.fc_hz.value() / 4;
  std::vector<std::int32_t> x;
  for (std::size_t i = 0; i < 40000; ++i) {
    x.push_back(static_cast<std::int32_t>(
        std::lround(level * 32768 *
                    std::sin(2 * std::numbers::pi * f * static_cast<double>(i) / design.fs_hz))));
  }
  return x;
}

TEST(IirCoreFidelity, PassbandSineSnr) {
  for (const SetCase& c : kSets) {
    const FloatDesign design = load_float_design(json_of(c));
    const double snr = core_snr_db(c, passband_sine(design, 0.5), 15000);
    std::cout << fmt::format(
        "[snr] {}: passband sine (fc/4, 0.5 FS) {:.1f} dB (threshold {:.0f})\n", c.folder, snr,
        c.min_sine_snr_db);
    EXPECT_GE(snr, c.min_sine_snr_db) << c.folder;
  }
}

TEST(IirCoreFidelity, MeasurementSosSineAtMinusOneDbfs) {
  // The first aim for the measurement filter was 80 dB for a -1 dBFS passband sine; contract v2
  // reaches the output rounding floor (97.1 dB), so the check is 96 dB.
  const SetCase& c = kSets.front();
  ASSERT_EQ(c.folder, "coeffs/measurement_sos");
  const double level = std::pow(10.0, -1.0 / 20.0);
  const double snr = core_snr_db(c, passband_sine(load_float_design(json_of(c)), level), 15000);
  std::cout << fmt::format("[snr] {}: passband sine (fc/4, -1 dBFS) {:.1f} dB (threshold 96)\n",
                           c.folder, snr);
  EXPECT_GE(snr, 96.0);
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
    EXPECT_LE(lc.amplitude, c.max_tail_lsb) << c.folder;
  }
}

TEST(IirCoreFidelity, LimitCycleBoundOfAFirstOrderSection) {
  // y_ext = round(0.5 y_ext1) with s = 2 and no error feedback: 1/A has l1 norm 2, so the
  // feedback rounding (1/8 LSB) circulates to at most 1/4 LSB (the dead band of y_ext in
  // IirCoreModel.ExtendedFeedbackAndDeadBand), the lo phase's truncation (below 2^-(s+F) =
  // 1/16 LSB) to 1/8 LSB, plus 1/2 LSB for the output rounding: 0.875 LSB.
  CoreConfig c;
  c.filter_order = 1;
  c.num_sections = 1;
  c.section_order = 1;
  c.sample_width = 8;
  c.coef_width = 8;
  c.coef_frac_bits = 2;
  c.feedback_shift = 2;
  c.acc_width = 32;
  c.rom = {0, 0, 0, 4, 0, 2, 0};
  EXPECT_NEAR(limit_cycle_bound_lsb(c), 0.875, 1e-9);
  // With E1 = 1 the rounding passes (1 - z^-1) / (1 - 0.5 z^-1), whose l1 norm is also 2.
  c.rom.back() = 1;
  EXPECT_NEAR(limit_cycle_bound_lsb(c), 0.875, 1e-9);
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
