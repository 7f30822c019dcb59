// SPDX-License-Identifier: MIT
// The multichannel sample model (IirSampleBank) against the cycle model (IirCore) under contract
// v2: channels interleaved at random, each with its own coefficient set or one shared set,
// full-scale stretches that clip, and a channel whose accumulator wraps beside one that does not;
// every output word and saturation flag must be equal. The checked-in multichannel sets (loco_*)
// join once they are regenerated for contract v2.
#include "iir_sample_bank.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "filter_json.h"
#include "iir_core.h"
#include "sample_model_configs.h"

namespace flange::model {
namespace {

// Three channels of the generator's shape (K = 3 biquads, 16-bit samples, P = 48), each its own
// set: one Butterworth, the Chebyshev's peaking sections before a Butterworth one, and the narrow
// Butterworth's last three sections (poles near z = 1).
CoreConfig three_sets() {
  const testing::Widths widths{16, 18, 16, 3, 48};
  const auto cheby = testing::cheby1_4_02();
  const auto butter6 = testing::butter6_low_01();
  const auto narrow = testing::butter8_low_001();
  CoreConfig c = testing::make_config("three_sets", butter6, widths);
  const CoreConfig second =
      testing::make_config("second", {cheby[0], cheby[1], butter6[2]}, widths);
  const CoreConfig third = testing::make_config("third", {narrow[1], narrow[2], narrow[3]}, widths);
  c.rom.insert(c.rom.end(), second.rom.begin(), second.rom.end());
  c.rom.insert(c.rom.end(), third.rom.begin(), third.rom.end());
  c.num_channels = 3;
  c.coef_sets = 3;
  validate_core_config(c);
  return c;
}

struct Mismatch {
  int n = -1;  // the first stream position that differs, -1 for none
  std::string what;
};

// `samples` words on random channels.
Mismatch compare(const CoreConfig& config, int samples, std::uint64_t seed) {
  IirCore core(config);
  IirSampleBank bank(config);
  std::mt19937_64 rng(seed);
  const auto hi = static_cast<std::int32_t>((std::int64_t{1} << (config.sample_width - 1)) - 1);
  const std::int32_t lo = -hi - 1;
  const auto span = static_cast<std::uint64_t>(std::int64_t{hi} - lo + 1);
  int saturated = 0;
  for (int n = 0; n < samples; ++n) {
    const int channel = static_cast<int>(rng() % static_cast<std::uint64_t>(config.num_channels));
    // Full-scale squares (half period some 250 words per channel) on 40% of the stream, uniform
    // words elsewhere.
    const int half = 250 * config.num_channels;
    const std::int32_t x =
        n % (10 * half) < 4 * half
            ? ((n / half) % 2 ? hi : lo)
            : static_cast<std::int32_t>(lo + static_cast<std::int64_t>(rng() % span));
    const StepResult want = core.step(x, channel);
    const SampleResult got = bank.step(x, channel);
    saturated += want.saturated ? 1 : 0;
    if (got.sample != want.sample || got.saturated != want.saturated) {
      return {n, "channel " + std::to_string(channel) + ": IirCore " + std::to_string(want.sample) +
                     (want.saturated ? " saturated" : "") + ", bank " + std::to_string(got.sample) +
                     (got.saturated ? " saturated" : "")};
    }
  }
  EXPECT_GT(saturated, 0) << "the stimulus never clipped";
  return {};
}

class IirSampleBankSet : public ::testing::TestWithParam<std::string> {};

TEST_P(IirSampleBankSet, MatchesTheCycleModelOnAMillionSamples) {
  const CoreConfig config = load_core_config(std::filesystem::path(FLANGE_SOURCE_DIR) /
                                             "tests/data/coeffs" / GetParam() / "filter.json");
  ASSERT_GT(config.num_channels, 1);
  const Mismatch m = compare(config, 1'000'000, 20261122);
  EXPECT_EQ(m.n, -1) << "first at " << m.n << ": " << m.what
                     << "\nreproduce: ctest --test-dir build -R 'IirSampleBankSet.*" << GetParam()
                     << "' --output-on-failure";
  IirSampleBank bank(config);
  for (int c = 0; c < config.num_channels; ++c) {
    EXPECT_FALSE(bank.channel(c).accumulator_can_wrap()) << "channel " << c;
  }
}

INSTANTIATE_TEST_SUITE_P(CheckedIn, IirSampleBankSet,
                         ::testing::Values("loco_ch4", "loco_ch12", "loco_sets3"),
                         [](const ::testing::TestParamInfo<std::string>& set) {
                           return set.param;
                         });

TEST(IirSampleBank, OwnSetPerChannelMatchesTheCycleModel) {
  const CoreConfig config = three_sets();
  const Mismatch m = compare(config, 300'000, 11);
  EXPECT_EQ(m.n, -1) << "first at " << m.n << ": " << m.what;
  IirSampleBank bank(config);
  for (int c = 0; c < 3; ++c) {
    EXPECT_FALSE(bank.channel(c).accumulator_can_wrap()) << "channel " << c;
    EXPECT_EQ(bank.channel(c).config().rom, config.channel_config(c).rom) << "channel " << c;
  }
}

TEST(IirSampleBank, SharedSetMatchesTheCycleModel) {
  CoreConfig config =
      testing::make_config("shared", testing::butter8_low_001(), {16, 18, 16, 7, 48});
  config.num_channels = 4;
  config.coef_sets = 1;
  const Mismatch m = compare(config, 200'000, 12);
  EXPECT_EQ(m.n, -1) << "first at " << m.n << ": " << m.what;
}

// Two channels of one narrow core (8-bit samples and words, F = 1, P = 16, one first-order
// section): channel 0's words are small, channel 1's are the largest and its sums wrap.
TEST(IirSampleBank, WrappingChannelBesideAnotherMatchesTheCycleModel) {
  CoreConfig config;
  config.name = "wrapping_pair";
  config.filter_order = 1;
  config.num_sections = 1;
  config.section_order = 1;
  config.sample_width = 8;
  config.coef_width = 8;
  config.coef_frac_bits = 1;
  config.feedback_shift = 0;
  config.acc_width = 16;
  config.num_channels = 2;
  config.coef_sets = 2;
  // W_b[0..1], W_a[1], H_b[0..1], H_a[1], E[1] per set.
  config.rom = {64, 64, 96, 0, 0, 0, 0, 127, 127, 127, 127, 127, 127, 1};
  validate_core_config(config);
  const Mismatch m = compare(config, 100'000, 13);
  EXPECT_EQ(m.n, -1) << "first at " << m.n << ": " << m.what;
  IirSampleBank bank(config);
  EXPECT_TRUE(bank.channel(1).accumulator_can_wrap());
  EXPECT_EQ(bank.channel(1).kernel(), SampleKernel::kTwoPhase);
}

TEST(IirSampleBank, RejectsBadChannelsAndResets) {
  const CoreConfig config = three_sets();
  IirSampleBank bank(config), fresh(config);
  EXPECT_EQ(bank.channels(), 3);
  EXPECT_THROW(bank.step(0, 3), std::out_of_range);
  EXPECT_THROW(bank.step(0, -1), std::out_of_range);
  EXPECT_THROW(bank.step(40000, 0), std::out_of_range);
  for (int n = 0; n < 1000; ++n) bank.step(n % 3 ? 20000 : -32768, n % 3);
  bank.reset();
  for (int n = 0; n < 1000; ++n) {
    ASSERT_EQ(bank.step(12345 - n, n % 3), fresh.step(12345 - n, n % 3)) << "after reset, " << n;
  }
  CoreConfig broken = config;
  broken.rom.pop_back();
  EXPECT_THROW(IirSampleBank{broken}, std::invalid_argument);
}

}  // namespace
}  // namespace flange::model
