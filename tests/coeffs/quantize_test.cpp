// SPDX-License-Identifier: MIT
// Quantisation for the hardware: the fractional-bit rule, the ROM words, the checks that
// refuse what will not work.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "design_error.h"
#include "generator.h"

namespace flange::coeffs {
namespace {

DesignRequest order_and_cutoff(int order, double fc_hz, double fs_hz, Structure structure) {
  DesignRequest request;
  request.fs_hz = fs_hz;
  request.order = order;
  request.fc_hz = fc_hz;
  request.structure = structure;
  return request;
}

TEST(Quantize, ReferenceSpecDesignsMeetTheirSpecAsSos) {
  std::ifstream file(std::string(FLANGE_SOURCE_DIR) + "/tests/data/butterworth_scipy.json");
  const nlohmann::json reference = nlohmann::json::parse(file);
  for (const auto& entry : reference["from_specs"]) {
    const auto& s = entry["spec"];
    DesignRequest request;
    request.fs_hz = s["fs_hz"];
    request.fp_hz = s["fp_hz"].get<double>();
    request.fa_hz = s["fa_hz"].get<double>();
    request.ap_db = s["ap_db"].get<double>();
    request.aa_db = s["aa_db"].get<double>();
    const DesignRecord record = generate_design(request, "test");
    EXPECT_TRUE(record.analysis.stable) << s.dump();
    EXPECT_TRUE(record.analysis.meets_spec) << s.dump() << ": " << record.analysis.rejection;
    EXPECT_TRUE(record.analysis.rejection.empty()) << record.analysis.rejection;
    ASSERT_TRUE(record.analysis.passband_loss_db.has_value());
    EXPECT_LE(*record.analysis.passband_loss_db, request.ap_db.value() + 0.01);
    EXPECT_GE(*record.analysis.stopband_atten_db, request.aa_db.value() - 0.01);
  }
}

TEST(Quantize, BiquadsGetSixteenFractionalBitsAndTheWholeAPort) {
  const DesignRecord record =
      generate_design(order_and_cutoff(7, 0.259, 100.0, Structure::kSos), "test");
  EXPECT_EQ(record.quantized.coef_frac_bits, 16);  // |a1| < 2 -> Q2.16 in 18 bits
  EXPECT_EQ(record.quantized.split_shift, 17);     // C - 1: the DSP48E1's P >>> 17
  EXPECT_EQ(record.quantized.section_count, 4);
  EXPECT_EQ(record.quantized.words.size(), 48u);  // 4 x (5 M + 2)
  EXPECT_EQ(record.quantized.feedback_shift, kDspAPortBits - 16);
}

TEST(Quantize, ErrorFeedbackIsTheRoundedDenominator) {
  // Narrow biquads have -a near (2, -1): E = (2, -1), so the rounding noise passes
  // (1 - z^-1)^2 / A(z), which cancels the double pole near z = 1.
  const DesignRecord record =
      generate_design(order_and_cutoff(7, 0.259, 100.0, Structure::kSos), "test");
  const QuantizedFilter& q = record.quantized;
  for (int k = 0; k < q.section_count; ++k) {
    const QuantizedSection& section = q.sections[static_cast<std::size_t>(k)];
    ASSERT_EQ(section.error_feedback.size(), 2u);
    for (int j = 1; j <= 2; ++j) {
      EXPECT_EQ(section.error_feedback[static_cast<std::size_t>(j - 1)],
                std::llround(-section.a[static_cast<std::size_t>(j)]));
      EXPECT_EQ(q.words[static_cast<std::size_t>(k * 12 + 4 * 2 + 1 + j)],
                section.error_feedback[static_cast<std::size_t>(j - 1)]);
    }
  }
  EXPECT_EQ(q.sections[1].error_feedback, (std::vector<std::int64_t>{2, -1}));
}

TEST(Quantize, WordsFitTheCoefficientWidthAndReproduceTheSectionValues) {
  for (Structure structure : {Structure::kSos, Structure::kDf1}) {
    const DesignRecord record =
        generate_design(order_and_cutoff(5, 0.5742, 6.0, structure), "test");
    const QuantizedFilter& q = record.quantized;
    const std::int64_t limit = std::int64_t{1} << (q.widths.coef_bits - 1);
    for (std::int64_t word : q.words) {
      EXPECT_LT(word, limit);
      EXPECT_GE(word, -limit);
    }
    // ROM order per section: lo b[0..M], lo -a[1..M], hi b[0..M], hi -a[1..M], E[1..M]; a
    // coefficient is (hi + lo 2^-L) 2^-F with lo in [0, 2^L).
    const int m = q.section_order;
    const int terms = 5 * m + 2;
    const auto value = [&](int k, int hi, int lo) {
      const std::int64_t lo_word = q.words[static_cast<std::size_t>(k * terms + lo)];
      EXPECT_GE(lo_word, 0);
      EXPECT_LT(lo_word, std::int64_t{1} << q.split_shift);
      return std::ldexp(static_cast<double>(q.words[static_cast<std::size_t>(k * terms + hi)]),
                        -q.coef_frac_bits) +
             std::ldexp(static_cast<double>(lo_word), -(q.coef_frac_bits + q.split_shift));
    };
    for (int k = 0; k < q.section_count; ++k) {
      const auto& section = q.sections[static_cast<std::size_t>(k)];
      for (int i = 0; i <= m; ++i) {
        EXPECT_EQ(value(k, 2 * m + 1 + i, i), section.b[static_cast<std::size_t>(i)]);
      }
      for (int j = 1; j <= m; ++j) {
        EXPECT_EQ(-value(k, 3 * m + 1 + j, m + j), section.a[static_cast<std::size_t>(j)]);
      }
    }
  }
}

TEST(Quantize, NumeratorCompensationKeepsTheDcGainOfANarrowFilter) {
  const DesignRecord record =
      generate_design(order_and_cutoff(7, 0.259, 100.0, Structure::kSos), "test");
  EXPECT_LT(std::abs(record.analysis.dc_gain_error_db), 1e-3);
  EXPECT_TRUE(record.analysis.stable);
}

TEST(Quantize, ThesisVehicleDirectFormIsRefusedAsUnstable) {
  const DesignRecord record =
      generate_design(order_and_cutoff(7, 0.259, 100.0, Structure::kDf1), "test");
  EXPECT_FALSE(record.analysis.stable);
  EXPECT_GT(record.analysis.max_pole_radius, 1.0);
  EXPECT_NE(record.analysis.rejection.find("outside the unit circle"), std::string::npos);
  EXPECT_NE(record.analysis.rejection.find("--structure sos"), std::string::npos);
}

TEST(Quantize, MeasurementDirectFormSurvivesEighteenBits) {
  const DesignRecord record =
      generate_design(order_and_cutoff(5, 0.5742, 6.0, Structure::kDf1), "test");
  EXPECT_TRUE(record.analysis.stable);
  EXPECT_TRUE(record.analysis.rejection.empty()) << record.analysis.rejection;
  EXPECT_EQ(record.quantized.coef_frac_bits, 15);  // max |a| = 3.99 -> 2 integer bits
}

TEST(Quantize, TooNarrowAnAccumulatorIsRefused) {
  DesignRequest request = order_and_cutoff(5, 0.5742, 6.0, Structure::kSos);
  request.widths.acc_bits = 30;
  EXPECT_THROW(generate_design(request, "test"), DesignRejected);
}

TEST(Quantize, HighOrderDirectFormWithoutFractionBitsIsRefused) {
  EXPECT_THROW(generate_design(order_and_cutoff(32, 1.0, 100.0, Structure::kDf1), "test"),
               DesignRejected);
}

TEST(Quantize, NumeratorWithoutFractionBitsIsRefused) {
  // A numerator 2^20 times too large leaves no fractional bit in 18-bit words: F would drop below
  // 1, and the accumulator's rounding constant 2^(F-1) would not exist.
  FloatDesign design = design_butterworth(2, 1.0, 6.0, std::nullopt);
  for (double& b : design.b) b = std::ldexp(b, 20);
  try {
    quantize(design, Structure::kDf1, HardwareWidths{});
    FAIL() << "accepted";
  } catch (const DesignRejected& e) {
    EXPECT_NE(std::string(e.what()).find("integer bits for its largest coefficient (325166)"),
              std::string::npos)
        << e.what();
  }
}

TEST(Quantize, EverySosOrderFromOneToThirtyTwoQuantisesStably) {
  for (int order = 1; order <= 32; ++order) {
    const DesignRecord record =
        generate_design(order_and_cutoff(order, 10.0, 100.0, Structure::kSos), "test");
    EXPECT_TRUE(record.analysis.stable) << "order " << order;
    EXPECT_TRUE(record.analysis.rejection.empty())
        << "order " << order << ": " << record.analysis.rejection;
    EXPECT_EQ(record.quantized.section_count, (order + 1) / 2);
  }
}

TEST(Quantize, FewerCoefficientBitsMissTheSpec) {
  DesignRequest request;
  request.fs_hz = 6.0;
  request.fp_hz = 0.21128;
  request.fa_hz = 0.975;
  request.ap_db = 0.1737;
  request.aa_db = 40.0;
  request.widths.coef_bits = 6;
  const DesignRecord record = generate_design(request, "test");
  EXPECT_FALSE(record.analysis.rejection.empty());
}

}  // namespace
}  // namespace flange::coeffs

namespace flange::coeffs {
namespace {

TEST(Quantize, WithoutASpecTheResponseMustFollowTheFloatDesign) {
  DesignRequest request = order_and_cutoff(12, 10.0, 100.0, Structure::kSos);
  request.widths.coef_bits = 4;
  const DesignRecord record = generate_design(request, "test");
  ASSERT_TRUE(record.analysis.passband_deviation_db.has_value());
  EXPECT_GT(*record.analysis.passband_deviation_db, 0.5);
  // The DC gain is judged first; 4-bit words miss both.
  EXPECT_NE(record.analysis.rejection.find("DC gain error"), std::string::npos)
      << record.analysis.rejection;
}

TEST(Quantize, ACutoffTooSmallForDoublePrecisionIsRefused) {
  EXPECT_THROW(generate_design(order_and_cutoff(4, 0.001, 1e6, Structure::kSos), "test"),
               DesignRejected);
}

}  // namespace
}  // namespace flange::coeffs
