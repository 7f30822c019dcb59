// SPDX-License-Identifier: MIT
// The bit-accurate model on hand-computed cases: rounding (twice), saturation (both steps), the
// extended-precision feedback, error feedback, lo words, the history layout, the accumulator
// wrap, and the cycle-level behaviour of the pins.
#include "iir_core.h"

#include <gtest/gtest.h>

#include <array>
#include <fstream>
#include <string>
#include <tuple>

#include "filter_json.h"
#include "iir_mac.h"

namespace flange::model {
namespace {

// One section of order 1, 8-bit samples, 8-bit words (L = 7), hi words only unless given:
// u = x << s, y_ext = ((2^(F-1+L) + W.u) >>> L) + B0 u + B1 u1 + A1 y_ext1 + E1 e1) >>> F,
// y = (y_ext + 2^(s-1)) >>> s.
CoreConfig tiny(std::int64_t b0, std::int64_t b1, std::int64_t a1, int f, int s,
                std::int64_t e1 = 0, std::array<std::int64_t, 3> lo = {0, 0, 0}) {
  CoreConfig c;
  c.name = "tiny";
  c.filter_order = 1;
  c.num_sections = 1;
  c.section_order = 1;
  c.sample_width = 8;
  c.coef_width = 8;
  c.coef_frac_bits = f;
  c.feedback_shift = s;
  c.acc_width = 32;
  c.rom = {lo[0], lo[1], lo[2], b0, b1, a1, e1};
  return c;
}

std::filesystem::path set_json(const std::string& set) {
  return std::filesystem::path(FLANGE_SOURCE_DIR) / "coeffs" / set / "filter.json";
}

TEST(IirCoreModel, RoundsHalfUp) {
  // B0 = 1 with F = 2 and s = 0 (one rounding): y = round(x / 4), ties towards +infinity.
  IirCore core(tiny(1, 0, 0, 2, 0));
  const std::vector<std::pair<std::int32_t, std::int32_t>> cases = {
      {2, 1}, {-2, 0}, {6, 2}, {-6, -1}, {1, 0}, {3, 1}, {-1, 0}, {-3, -1}, {127, 32}, {-128, -32}};
  for (const auto& [x, y] : cases) {
    EXPECT_EQ(core.step(x).sample, y) << "x = " << x;
  }
}

TEST(IirCoreModel, SaturatesBothWaysAndFlags) {
  // B0 = 8 with F = 2: gain 2.
  IirCore core(tiny(8, 0, 0, 2, 0));
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
  // y[n] = x[n] + 0.5 y[n-1]: B0 = 4 (1.0 in Q.2), -a1 = 2 (0.5), s = 2: every signal has 2 more
  // fractional bits (quarter LSB) and y_ext is fed back as it is. Without error feedback an
  // impulse of 64 halves each step until rounding half up holds y_ext at 1 (the dead band
  // 0.5 / (1 - 0.5) = 1 LSB of y_ext, a quarter of an output LSB), which the output rounds to 0.
  IirCore core(tiny(4, 0, 2, 2, 2));
  const std::vector<std::int64_t> ext = {256, 128, 64, 32, 16, 8, 4, 2, 1, 1};
  const std::vector<std::int32_t> expected = {64, 32, 16, 8, 4, 2, 1, 1, 0, 0};
  for (std::size_t n = 0; n < expected.size(); ++n) {
    EXPECT_EQ(core.step(n == 0 ? 64 : 0).sample, expected[n]) << "n = " << n;
    EXPECT_EQ(core.lr()[2], ext[n]) << "y_ext, n = " << n;  // line 1, age 0
  }
  // Negative side: y_ext halves to -1, then round(-0.5) = 0 ends it.
  IirCore neg(tiny(4, 0, 2, 2, 2));
  const std::vector<std::int64_t> ext_neg = {-256, -128, -64, -32, -16, -8, -4, -2, -1, 0, 0};
  const std::vector<std::int32_t> expected_neg = {-64, -32, -16, -8, -4, -2, -1, 0, 0, 0, 0};
  for (std::size_t n = 0; n < expected_neg.size(); ++n) {
    EXPECT_EQ(neg.step(n == 0 ? -64 : 0).sample, expected_neg[n]) << "n = " << n;
    EXPECT_EQ(neg.lr()[2], ext_neg[n]) << "y_ext, n = " << n;
  }
}

TEST(IirCoreModel, ErrorFeedbackEndsTheDeadBand) {
  // The same filter with E1 = round(0.5) = 1: e = (acc mod 4) - 2 is what y_ext's rounding
  // dropped. While y_ext halves exactly e is 0; at y_ext = 1 the sum 2 + 2 = 4 rounds to 1 and
  // drops e = -2, which the next sum takes back: 2 + 2 - 2 = 2 rounds to 0, and there it stays.
  IirCore core(tiny(4, 0, 2, 2, 2, 1));
  const std::vector<std::int64_t> ext = {256, 128, 64, 32, 16, 8, 4, 2, 1, 1, 0, 0};
  const std::vector<std::int64_t> err = {0, 0, 0, 0, 0, 0, 0, 0, 0, -2, 0, 0};
  for (std::size_t n = 0; n < ext.size(); ++n) {
    core.step(n == 0 ? 64 : 0);
    EXPECT_EQ(core.lr()[2], ext[n]) << "y_ext, n = " << n;  // line 1, age 0
    EXPECT_EQ(core.lr()[4], err[n]) << "e, n = " << n;      // line K + 1 = 2, age 0
  }
}

TEST(IirCoreModel, LoWordsAddAFractionOfAHiLsb) {
  // b0 = W 2^-L 2^-F = 64 / 2^7 / 4 = 1/8 from the lo word alone, s = 0. The lo phase
  // (2^(F-1+L) + 64 x) >>> 7 is floored before the hi phase: x = 4 gives (256 + 256) >>> 7 = 4,
  // y = 4 >>> 2 = 1 (0.5 rounds up); x = -4: 0, y = 0 (-0.5 rounds up); x = 3: 448 >>> 7 = 3,
  // y = 0; x = 12: (256 + 768) >>> 7 = 8, y = 2 (1.5 rounds up).
  IirCore core(tiny(0, 0, 0, 2, 0, 0, {64, 0, 0}));
  EXPECT_EQ(core.step(4).sample, 1);
  EXPECT_EQ(core.step(-4).sample, 0);
  EXPECT_EQ(core.step(3).sample, 0);
  EXPECT_EQ(core.step(12).sample, 2);
  EXPECT_EQ(core.step(-12).sample, -1);  // (256 - 768) >>> 7 = -4, -4 >>> 2 = -1
}

TEST(IirCoreModel, OutputIsRoundedFromTheExtendedValue) {
  // Double rounding: y = round(round(v to F) to s fewer bits), not round(v to s fewer bits).
  // B0 = 7 with F = 4 and s = 2 (7/16 of a sample): x = 1 gives v = 0.4375 LSB; y_ext =
  // (7 * 4 + 8) >>> 4 = 2 (0.5 LSB), y = (2 + 2) >>> 2 = 1, where rounding v directly would give
  // 0. They differ only for a fraction of v in [1/2 - 2^-(s+1), 1/2).
  IirCore core(tiny(7, 0, 0, 4, 2));
  StepResult r = core.step(1);
  EXPECT_EQ(core.lr()[2], 2);
  EXPECT_EQ(r.sample, 1);
  r = core.step(-1);  // v = -0.4375: y_ext = (-28 + 8) >>> 4 = -2, y = (-2 + 2) >>> 2 = 0
  EXPECT_EQ(core.lr()[2], -2);
  EXPECT_EQ(r.sample, 0);
  r = core.step(3);  // v = 1.3125: y_ext = 92 >>> 4 = 5, y = 7 >>> 2 = 1
  EXPECT_EQ(core.lr()[2], 5);
  EXPECT_EQ(r.sample, 1);
}

TEST(IirCoreModel, SaturatesInEitherRoundingStep) {
  // B0 = 16 (1.0), B1 = 1 (1/16) with F = 4 and s = 2: y_ext has 10 bits, [-512, 511]. In
  // accumulator LSB the sum is 4 times the figures below (u = 4 x, preload 8), so y_ext = (16 x +
  // x1 + 2) >>> 2 as written.
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
  // Two sections of order 1 with s = 1 and F = 3; section outputs are exact (no feedback).
  CoreConfig c = tiny(8, 0, 0, 3, 1);
  c.num_sections = 2;
  c.filter_order = 2;
  c.rom = {0, 0, 0, 8, 0, 0, 0,    // section 0: y = x
           0, 0, 0, 16, 0, 0, 0};  // section 1: y = 2 x, from section 0's y_ext as it is
  IirCore core(c);
  EXPECT_EQ(core.step(3).sample, 6);
  EXPECT_EQ(core.step(5).sample, 10);
  // Lines of D + s-bit words: x[n] << s, x[n-1] << s | y0_ext[n], y0_ext[n-1] | y1_ext[n],
  // y1_ext[n-1] (y_ext is the output with s = 1 more fractional bit), then each section's
  // rounding errors (none: the sums are exact).
  EXPECT_EQ(core.lr(), (std::vector<std::int64_t>{10, 6, 10, 6, 20, 12, 0, 0, 0, 0}));
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
  // L = T + (K - 1) S + 4 with T = 5M + 2 terms per section and S = T + max(0, 3 - 2M): for
  // biquads (T = 12) and a single section that is the MACs per sample plus 4.
  const std::vector<std::pair<std::string, int>> sets = {
      {"measurement_sos", 36 + 4}, {"measurement_df1", 27 + 4}, {"vehicle_sos", 48 + 4}};
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
  EXPECT_EQ(a.valid_cycle - a.accept_cycle, 52u);
  EXPECT_EQ(b.accept_cycle, a.valid_cycle) << "a sample is accepted in the valid cycle";
}

TEST(IirCoreModel, PinsOverOneComputation) {
  IirCore core(tiny(4, 0, 0, 2, 0));  // latency T + 4 = 7 + 4 = 11
  ASSERT_EQ(core.latency_cycles(), 11);
  EXPECT_FALSE(core.pins(5).busy);
  ASSERT_TRUE(core.strobe(5, 9));
  EXPECT_FALSE(core.pins(5).busy) << "busy rises at the edge that ends the EN cycle";
  for (std::uint64_t c = 6; c < 16; ++c) {
    const Pins p = core.pins(c);
    EXPECT_TRUE(p.busy) << c;
    EXPECT_FALSE(p.sample_valid) << c;
    EXPECT_EQ(p.sample, 0) << c;
  }
  const Pins done = core.pins(16);
  EXPECT_FALSE(done.busy);
  EXPECT_TRUE(done.sample_valid);
  EXPECT_EQ(done.sample, 9);
  const Pins after = core.pins(17);
  EXPECT_FALSE(after.sample_valid);
  EXPECT_EQ(after.sample, 9) << "sample_o holds the last output";
}

TEST(IirCoreModel, OverrunDropsTheSample) {
  IirCore core(tiny(4, 0, 0, 2, 0));
  ASSERT_TRUE(core.strobe(1, 10));
  EXPECT_FALSE(core.strobe(2, 99)) << "busy: dropped";
  EXPECT_FALSE(core.pins(2).overrun);
  EXPECT_TRUE(core.pins(3).overrun);
  EXPECT_EQ(core.pins(12).sample, 10);
  EXPECT_TRUE(core.pins(12).sample_valid);
  const auto next = core.strobe(12, 20);
  ASSERT_TRUE(next) << "accepted in the valid cycle";
  // The dropped 99 never entered the history: the line holds 20 and 10.
  EXPECT_EQ(core.lr()[0], 20);
  EXPECT_EQ(core.lr()[1], 10);
  EXPECT_TRUE(core.pins(30).overrun) << "sticky";
}

TEST(IirCoreModel, FlagEventBeatsClearInTheSameEdge) {
  IirCore core(tiny(4, 0, 0, 2, 0));
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
  // issues T = 7 cycles after the accept and is written back 3 cycles later, so the flag shows
  // from accept + 11; the output comes at accept + T + S + 4 = accept + 7 + 8 + 4 = accept + 19
  // (S = T + 1: with M = 1 the next section's W_b[0] waits a cycle for the write-back).
  CoreConfig c = tiny(8, 0, 0, 2, 0);
  c.num_sections = 2;
  c.filter_order = 2;
  c.rom = {0, 0, 0, 8, 0, 0, 0, 0, 0, 0, 2, 0, 0, 0};
  IirCore core(c);
  ASSERT_EQ(core.latency_cycles(), 19);
  const auto r = core.strobe(10, 100);
  ASSERT_TRUE(r);
  EXPECT_TRUE(r->saturated);
  EXPECT_EQ(r->sample, 64);  // 127 * 0.5 = 63.5, rounded half up
  EXPECT_FALSE(core.pins(20).saturation);
  EXPECT_TRUE(core.pins(21).saturation);
  EXPECT_TRUE(core.pins(29).sample_valid);
}

TEST(IirCoreModel, ResetCancelsTheComputationInFlight) {
  IirCore core(tiny(4, 0, 0, 2, 0));
  ASSERT_TRUE(core.strobe(1, 10));
  core.reset(11);  // the output would be seen in cycle 12
  const Pins p = core.pins(12);
  EXPECT_FALSE(p.sample_valid);
  EXPECT_FALSE(p.busy);
  EXPECT_EQ(p.sample, 0);
  EXPECT_EQ(core.lr()[0], 0) << "history cleared";
  EXPECT_TRUE(core.strobe(12, 5)) << "ready right after reset";

  IirCore late(tiny(4, 0, 0, 2, 0));
  ASSERT_TRUE(late.strobe(1, 10));
  late.reset(12);  // the output is already visible in cycle 12
  EXPECT_TRUE(late.pins(12).sample_valid);
  EXPECT_EQ(late.pins(13).sample, 0);
}

TEST(IirCoreModel, StrobeDuringResetIsIgnored) {
  IirCore core(tiny(4, 0, 0, 2, 0));
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
  IirCore core(tiny(4, 0, 0, 2, 0));
  EXPECT_THROW(core.step(128), std::out_of_range);
  EXPECT_THROW(core.step(-129), std::out_of_range);
  core.pins(10);
  EXPECT_THROW(core.pins(9), std::logic_error) << "time runs forwards";
  CoreConfig bad = tiny(4, 0, 0, 2, 0);
  bad.rom.pop_back();
  EXPECT_THROW(IirCore{bad}, std::invalid_argument);
  bad = tiny(200, 0, 0, 2, 0);  // does not fit 8 bits
  EXPECT_THROW(IirCore{bad}, std::invalid_argument);
  bad = tiny(4, 0, 0, 0, 0);  // F = 0: no rounding constant 2^(F-1)
  EXPECT_THROW(IirCore{bad}, std::invalid_argument);
  bad = tiny(4, 0, 0, 2, 0, 0, {-1, 0, 0});  // a lo word below 0
  EXPECT_THROW(IirCore{bad}, std::invalid_argument);
  bad = tiny(4, 0, 0, 9, 0);  // F = 9 > D + s: the error word would not fit the operand
  EXPECT_THROW(IirCore{bad}, std::invalid_argument);
}

}  // namespace
}  // namespace flange::model
