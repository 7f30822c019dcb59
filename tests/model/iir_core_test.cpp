// SPDX-License-Identifier: MIT
// The bit-accurate model on hand-computed cases: rounding (twice), saturation (both steps), the
// extended-precision feedback, the history layout, the accumulator wrap, and the cycle-level
// behaviour of the pins.
#include "iir_core.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <tuple>

#include "filter_json.h"
#include "iir_mac.h"

namespace flange::model {
namespace {

// One section of order 1, 8-bit samples, 8-bit words, s = Fb - Fa:
// y_ext = (B0 x + B1 x1 + A1 y_ext1 + 2^(Fa-1)) >>> Fa, y = (y_ext + 2^(s-1)) >>> s.
CoreConfig tiny(std::int64_t b0, std::int64_t b1, std::int64_t a1, int fb, int fa) {
  CoreConfig c;
  c.name = "tiny";
  c.filter_order = 1;
  c.num_sections = 1;
  c.section_order = 1;
  c.sample_width = 8;
  c.coef_width = 8;
  c.num_frac_bits = fb;
  c.coef_frac_bits = fa;
  c.feedback_shift = fb - fa;
  c.acc_width = 32;
  c.rom = {b0, b1, a1};
  return c;
}

std::filesystem::path set_json(const std::string& set) {
  return std::filesystem::path(FLANGE_SOURCE_DIR) / "coeffs" / set / "filter.json";
}

TEST(IirCoreModel, RoundsHalfUp) {
  // B0 = 1 with Fb = Fa = 2 (s = 0, one rounding): y = round(x / 4), ties towards +infinity.
  IirCore core(tiny(1, 0, 0, 2, 2));
  const std::vector<std::pair<std::int32_t, std::int32_t>> cases = {
      {2, 1}, {-2, 0}, {6, 2}, {-6, -1}, {1, 0}, {3, 1}, {-1, 0}, {-3, -1}, {127, 32}, {-128, -32}};
  for (const auto& [x, y] : cases) {
    EXPECT_EQ(core.step(x).sample, y) << "x = " << x;
  }
}

TEST(IirCoreModel, SaturatesBothWaysAndFlags) {
  // B0 = 8 with Fb = 2: gain 2.
  IirCore core(tiny(8, 0, 0, 2, 2));
  StepResult r = core.step(50);
  EXPECT_EQ(r.sample, 100);
  EXPECT_FALSE(r.saturated);
  r = core.step(100);
  EXPECT_EQ(r.sample, 127);
  EXPECT_TRUE(r.saturated);
  r = core.step(-100);
  EXPECT_EQ(r.sample, -128);
  EXPECT_TRUE(r.saturated);
  r = core.step(-64);
  EXPECT_EQ(r.sample, -128);
  EXPECT_FALSE(r.saturated) << "-128 is representable: no clip";
  EXPECT_TRUE(core.pins(r.valid_cycle).saturation) << "the flag is sticky";
}

TEST(IirCoreModel, ExtendedFeedbackAndDeadBand) {
  // y[n] = x[n] + 0.5 y[n-1]: B0 = 16 (Q.4), -a1 = 2 (Q.2), so s = 2: y_ext has 2 more fractional
  // bits (quarter LSB) and is fed back as it is. An impulse of 64 halves each step until rounding
  // half up holds y_ext at 1 (the dead band 0.5 / (1 - 0.5) = 1 LSB of y_ext, a quarter of an
  // output LSB), which the output rounds to 0. (Fed back at 8 bits, y would stick at 1 LSB.)
  IirCore core(tiny(16, 0, 2, 4, 2));
  const std::vector<std::int64_t> ext = {256, 128, 64, 32, 16, 8, 4, 2, 1, 1};
  const std::vector<std::int32_t> expected = {64, 32, 16, 8, 4, 2, 1, 1, 0, 0};
  for (std::size_t n = 0; n < expected.size(); ++n) {
    EXPECT_EQ(core.step(n == 0 ? 64 : 0).sample, expected[n]) << "n = " << n;
    EXPECT_EQ(core.lr()[2], ext[n]) << "y_ext, n = " << n;  // line 1, age 0
  }
  // Negative side: y_ext halves to -1, then round(-0.5) = 0 ends it.
  IirCore neg(tiny(16, 0, 2, 4, 2));
  const std::vector<std::int64_t> ext_neg = {-256, -128, -64, -32, -16, -8, -4, -2, -1, 0, 0};
  const std::vector<std::int32_t> expected_neg = {-64, -32, -16, -8, -4, -2, -1, 0, 0, 0, 0};
  for (std::size_t n = 0; n < expected_neg.size(); ++n) {
    EXPECT_EQ(neg.step(n == 0 ? -64 : 0).sample, expected_neg[n]) << "n = " << n;
    EXPECT_EQ(neg.lr()[2], ext_neg[n]) << "y_ext, n = " << n;
  }
}

TEST(IirCoreModel, OutputIsRoundedFromTheExtendedValue) {
  // Double rounding: y = round(round(v to Fa) to Fb), not round(v to Fb). B0 = 7 (7/16) with
  // s = 2: x = 1 gives v = 0.4375 LSB; y_ext = (7 + 2) >>> 2 = 2 (0.5 LSB), y = (2 + 2) >>> 2 = 1,
  // where rounding v directly would give 0. They differ only for a fraction of v in
  // [1/2 - 2^-(s+1), 1/2).
  IirCore core(tiny(7, 0, 0, 4, 2));
  StepResult r = core.step(1);
  EXPECT_EQ(core.lr()[2], 2);
  EXPECT_EQ(r.sample, 1);
  r = core.step(-1);  // v = -0.4375: y_ext = (-7 + 2) >>> 2 = -2, y = (-2 + 2) >>> 2 = 0
  EXPECT_EQ(core.lr()[2], -2);
  EXPECT_EQ(r.sample, 0);
  r = core.step(3);  // v = 1.3125: y_ext = 23 >>> 2 = 5, y = 7 >>> 2 = 1
  EXPECT_EQ(core.lr()[2], 5);
  EXPECT_EQ(r.sample, 1);
}

TEST(IirCoreModel, SaturatesInEitherRoundingStep) {
  // B0 = 16 (1.0), B1 = 1 (1/16) with s = 2: y_ext has 10 bits, [-512, 511].
  const auto run = [](std::int32_t x1, std::int32_t x) {
    IirCore core(tiny(16, 1, 0, 4, 2));
    core.step(x1);
    const StepResult r = core.step(x);
    return std::make_tuple(core.lr()[2], r.sample, r.saturated);
  };
  // 16 * 127 + 5 = 2037: y_ext = 2039 >>> 2 = 509, y = 511 >>> 2 = 127: no clip.
  EXPECT_EQ(run(5, 127), std::make_tuple(std::int64_t{509}, 127, false));
  // 16 * 127 + 8 = 2040: y_ext = 510 fits 10 bits, but y = 512 >>> 2 = 128 does not fit 8: the
  // second step clips to 127 and flags it, while the history keeps 510.
  EXPECT_EQ(run(8, 127), std::make_tuple(std::int64_t{510}, 127, true));
  // 16 * 127 + 127 = 2159: y_ext = 540 clips to 511 (and y to 127).
  EXPECT_EQ(run(127, 127), std::make_tuple(std::int64_t{511}, 127, true));
  // -2048 - 128 = -2176: y_ext = -544 clips to -512, which rounds to -128 without a clip.
  EXPECT_EQ(run(-128, -128), std::make_tuple(std::int64_t{-512}, -128, true));
  // -2048 - 8 = -2056: y_ext = floor(-2054 / 4) = -514 clips to -512.
  EXPECT_EQ(run(-8, -128), std::make_tuple(std::int64_t{-512}, -128, true));
  // -2048 + 0 = -2048: y_ext = floor(-2046 / 4) = -512 exactly: no clip anywhere.
  EXPECT_EQ(run(0, -128), std::make_tuple(std::int64_t{-512}, -128, false));
}

TEST(IirCoreModel, HistoryLayoutNewestFirst) {
  // Two sections of order 1 with s = 1 (Fb = 3, Fa = 2); section outputs are exact (no feedback).
  CoreConfig c = tiny(8, 0, 0, 3, 2);
  c.num_sections = 2;
  c.filter_order = 2;
  c.rom = {8, 0, 0, 16, 0, 0};  // section 0: y = x; section 1: y = 2 x
  IirCore core(c);
  EXPECT_EQ(core.step(3).sample, 6);
  EXPECT_EQ(core.step(5).sample, 10);
  // Lines of D + s-bit words: x[n] << s, x[n-1] << s | y0_ext[n], y0_ext[n-1] | y1_ext[n],
  // y1_ext[n-1]; y_ext is the output with s = 1 more fractional bit.
  EXPECT_EQ(core.lr(), (std::vector<std::int64_t>{10, 6, 10, 6, 20, 12}));
}

TEST(IirCoreModel, AccumulatorWrapsLikeThePRegister) {
  EXPECT_EQ(wrap_to_width(std::uint64_t{1} << 47, 48), -(std::int64_t{1} << 47));
  EXPECT_EQ(wrap_to_width((std::uint64_t{1} << 47) - 1, 48), (std::int64_t{1} << 47) - 1);
  EXPECT_EQ(wrap_to_width(~std::uint64_t{0}, 48), -1);
  EXPECT_EQ(wrap_to_width(std::uint64_t{1} << 48, 48), 0);
  EXPECT_EQ(wrap_to_width(0xFFu, 8), -1);
  EXPECT_EQ(wrap_to_width(0x80u, 8), -128);
  // P <= P + A * B with a negative product, modulo 2^64, then read back at 48 bits.
  EXPECT_EQ(wrap_to_width(mac(5, -3, 4), 48), -7);
  // A sum that leaves 12 bits wraps like a 12-bit register would: 2047 + 1 -> -2048.
  EXPECT_EQ(wrap_to_width(mac(2047, 1, 1), 12), -2048);
}

TEST(IirCoreModel, LatencyIsMacsPlusFourWhenSectionsOverlap) {
  // L = T + (K - 1) max(T, 4) + 4 with T = 2M + 1 terms per section: for biquads (T = 5) and a
  // single section that is the MACs per sample plus 4.
  const std::vector<std::pair<std::string, int>> sets = {
      {"measurement_sos", 15 + 4}, {"measurement_df1", 11 + 4}, {"vehicle_sos", 20 + 4}};
  for (const auto& [set, cycles] : sets) {
    const IirCore core(load_core_config(set_json(set)));
    EXPECT_EQ(core.latency_cycles(), cycles) << set;
    EXPECT_EQ(core.cycles_per_sample(), cycles) << set;
  }
}

TEST(IirCoreModel, StepStreamsBackToBack) {
  IirCore core(load_core_config(set_json("vehicle_sos")));
  const StepResult a = core.step(100);
  const StepResult b = core.step(200);
  EXPECT_EQ(a.valid_cycle - a.accept_cycle, 24u);
  EXPECT_EQ(b.accept_cycle, a.valid_cycle) << "a sample is accepted in the valid cycle";
}

TEST(IirCoreModel, PinsOverOneComputation) {
  IirCore core(tiny(4, 0, 0, 2, 2));  // latency T + 4 = 3 + 4 = 7
  ASSERT_EQ(core.latency_cycles(), 7);
  EXPECT_FALSE(core.pins(5).busy);
  ASSERT_TRUE(core.strobe(5, 9));
  EXPECT_FALSE(core.pins(5).busy) << "busy rises at the edge that ends the EN cycle";
  for (std::uint64_t c = 6; c < 12; ++c) {
    const Pins p = core.pins(c);
    EXPECT_TRUE(p.busy) << c;
    EXPECT_FALSE(p.sample_valid) << c;
    EXPECT_EQ(p.sample, 0) << c;
  }
  const Pins done = core.pins(12);
  EXPECT_FALSE(done.busy);
  EXPECT_TRUE(done.sample_valid);
  EXPECT_EQ(done.sample, 9);
  const Pins after = core.pins(13);
  EXPECT_FALSE(after.sample_valid);
  EXPECT_EQ(after.sample, 9) << "sample_o holds the last output";
}

TEST(IirCoreModel, OverrunDropsTheSample) {
  IirCore core(tiny(4, 0, 0, 2, 2));
  ASSERT_TRUE(core.strobe(1, 10));
  EXPECT_FALSE(core.strobe(2, 99)) << "busy: dropped";
  EXPECT_FALSE(core.pins(2).overrun);
  EXPECT_TRUE(core.pins(3).overrun);
  EXPECT_EQ(core.pins(8).sample, 10);
  EXPECT_TRUE(core.pins(8).sample_valid);
  const auto next = core.strobe(8, 20);
  ASSERT_TRUE(next) << "accepted in the valid cycle";
  // The dropped 99 never entered the history: the line holds 20 and 10.
  EXPECT_EQ(core.lr()[0], 20);
  EXPECT_EQ(core.lr()[1], 10);
  EXPECT_TRUE(core.pins(20).overrun) << "sticky";
}

TEST(IirCoreModel, FlagEventBeatsClearInTheSameEdge) {
  IirCore core(tiny(4, 0, 0, 2, 2));
  ASSERT_TRUE(core.strobe(1, 10));
  core.strobe(3, 0);    // overrun, visible from cycle 4
  core.clear_flags(3);  // clear at the same edge: the event wins
  EXPECT_TRUE(core.pins(4).overrun);
  core.clear_flags(4);  // nothing pending: cleared from cycle 5
  EXPECT_TRUE(core.pins(4).overrun);
  EXPECT_FALSE(core.pins(5).overrun);
}

TEST(IirCoreModel, SaturationFlagRisesWhenTheSectionWritesBack) {
  // Two first-order sections; only section 0 clips (gain 2 then 0.5). Section 0's last term
  // issues T = 3 cycles after the accept and is written back 3 cycles later, so the flag shows
  // from accept + 7; the output comes at accept + T + max(T, 4) + 4 = accept + 11.
  CoreConfig c = tiny(8, 0, 0, 2, 2);
  c.num_sections = 2;
  c.filter_order = 2;
  c.rom = {8, 0, 0, 2, 0, 0};
  IirCore core(c);
  ASSERT_EQ(core.latency_cycles(), 11);
  const auto r = core.strobe(10, 100);
  ASSERT_TRUE(r);
  EXPECT_TRUE(r->saturated);
  EXPECT_EQ(r->sample, 64);  // 127 * 0.5 = 63.5, rounded half up
  EXPECT_FALSE(core.pins(16).saturation);
  EXPECT_TRUE(core.pins(17).saturation);
  EXPECT_TRUE(core.pins(21).sample_valid);
}

TEST(IirCoreModel, ResetCancelsTheComputationInFlight) {
  IirCore core(tiny(4, 0, 0, 2, 2));
  ASSERT_TRUE(core.strobe(1, 10));
  core.reset(7);  // the output would be seen in cycle 8
  const Pins p = core.pins(8);
  EXPECT_FALSE(p.sample_valid);
  EXPECT_FALSE(p.busy);
  EXPECT_EQ(p.sample, 0);
  EXPECT_EQ(core.lr()[0], 0) << "history cleared";
  EXPECT_TRUE(core.strobe(8, 5)) << "ready right after reset";

  IirCore late(tiny(4, 0, 0, 2, 2));
  ASSERT_TRUE(late.strobe(1, 10));
  late.reset(8);  // the output is already visible in cycle 8
  EXPECT_TRUE(late.pins(8).sample_valid);
  EXPECT_EQ(late.pins(9).sample, 0);
}

TEST(IirCoreModel, StrobeDuringResetIsIgnored) {
  IirCore core(tiny(4, 0, 0, 2, 2));
  core.reset(3);
  EXPECT_FALSE(core.strobe(3, 10));
  EXPECT_FALSE(core.pins(4).overrun);
  EXPECT_FALSE(core.pins(4).busy);
}

// The short form of docs/fixed_point.md that heads both the model and the RTL: from the symbol
// line to the first empty comment line, word for word.
std::string contract_paragraph(const std::filesystem::path& file) {
  std::ifstream in(std::filesystem::path(FLANGE_SOURCE_DIR) / file);
  std::string line, paragraph;
  bool inside = false;
  while (std::getline(in, line)) {
    if (line.starts_with("// D = SampleWidth")) inside = true;
    if (inside && line == "//") break;
    if (inside) paragraph += line + "\n";
  }
  return paragraph;
}

TEST(IirCoreModel, ContractParagraphMatchesTheRtlHeader) {
  const std::string model = contract_paragraph("model/iir_core.h");
  const std::string rtl = contract_paragraph("rtl/iir_core.sv");
  EXPECT_NE(model.find("- Rounding:"), std::string::npos) << model;
  EXPECT_NE(model.find("- Timing:"), std::string::npos) << model;
  EXPECT_EQ(model, rtl) << "the fixed-point paragraphs of model/iir_core.h and rtl/iir_core.sv "
                           "differ; both repeat docs/fixed_point.md";
}

TEST(IirCoreModel, RejectsIllegalInput) {
  IirCore core(tiny(4, 0, 0, 2, 2));
  EXPECT_THROW(core.step(128), std::out_of_range);
  EXPECT_THROW(core.step(-129), std::out_of_range);
  core.pins(10);
  EXPECT_THROW(core.pins(9), std::logic_error) << "time runs forwards";
  CoreConfig bad = tiny(4, 0, 0, 2, 2);
  bad.rom.pop_back();
  EXPECT_THROW(IirCore{bad}, std::invalid_argument);
  bad = tiny(200, 0, 0, 2, 2);  // does not fit 8 bits
  EXPECT_THROW(IirCore{bad}, std::invalid_argument);
  bad = tiny(4, 0, 0, 2, 0);  // Fa = 0: no rounding constant 2^(Fa-1)
  EXPECT_THROW(IirCore{bad}, std::invalid_argument);
}

}  // namespace
}  // namespace flange::model
