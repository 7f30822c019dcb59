// SPDX-License-Identifier: MIT
// The multichannel contract of the model (model/iir_core.h, "Channels"): channels share the MAC
// and nothing else, and the per-channel sample bank gives the cycle model's samples and flags.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <random>
#include <vector>

#include "filter_json.h"
#include "iir_core.h"
#include "iir_sample_bank.h"

namespace flange::model {
namespace {

// Three channels of one first-order section (8-bit samples and words), a set per channel:
// channel c's numerator is b0 = (4 + 4c) / 8, so the channels' outputs differ.
CoreConfig three_channels() {
  CoreConfig c;
  c.name = "three";
  c.filter_order = 1;
  c.num_sections = 1;
  c.section_order = 1;
  c.sample_width = 8;
  c.coef_width = 8;
  c.coef_frac_bits = 3;
  c.feedback_shift = 1;
  c.acc_width = 32;
  c.num_channels = 3;
  c.coef_sets = 3;
  c.rom = {0, 0, 0, 4, 2, 4, 0, 0, 0, 0, 8, 2, 4, 0, 0, 0, 0, 12, 2, 4, 1};
  return c;
}

std::filesystem::path loco_ch4_json() {
  return std::filesystem::path(FLANGE_SOURCE_DIR) / "tests/data/coeffs/loco_ch4/filter.json";
}

TEST(IirCoreChannels, EachChannelIsAOneChannelCoreFedItsOwnSamples) {
  const CoreConfig config = three_channels();
  IirCore shared(config);
  std::vector<IirCore> alone;
  for (int c = 0; c < 3; ++c) alone.emplace_back(config.channel_config(c));
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> sample(-128, 127), channel(0, 2);
  for (int n = 0; n < 3000; ++n) {
    const int c = channel(rng);
    const std::int32_t x = sample(rng);
    const StepResult got = shared.step(x, c);
    const StepResult want = alone[static_cast<std::size_t>(c)].step(x);
    ASSERT_EQ(got.sample, want.sample) << "n = " << n << ", channel " << c;
    ASSERT_EQ(got.saturated, want.saturated) << "n = " << n;
    ASSERT_EQ(got.channel, c);
    ASSERT_EQ(shared.lr(c), alone[static_cast<std::size_t>(c)].lr());
  }
}

TEST(IirCoreChannels, PinsCarryTheChannelAndPerChannelFlags) {
  IirCore core(three_channels());
  const auto first = core.strobe(1, 100, 2);
  ASSERT_TRUE(first);
  EXPECT_FALSE(core.strobe(2, 5, 1)) << "busy: dropped";
  const Pins during = core.pins(3);
  EXPECT_EQ(during.overrun, 1u << 1) << "only channel 1's bit";
  const Pins out = core.pins(first->valid_cycle);
  EXPECT_TRUE(out.sample_valid);
  EXPECT_EQ(out.channel, 2);
  EXPECT_EQ(out.sample, first->sample);
  EXPECT_EQ(out.saturation, 1u << 2) << "100 x 24/16 = 150 clips channel 2 only";
}

TEST(IirCoreChannels, ChannelBeyondTheCountIsDroppedAndFlagged) {
  IirCore core(three_channels());
  EXPECT_EQ(core.channel_width(), 2);
  EXPECT_FALSE(core.strobe(1, 10, 3)) << "channel 3 of 3";
  const Pins p = core.pins(2);
  EXPECT_TRUE(p.channel_error);
  EXPECT_FALSE(p.busy) << "nothing was accepted";
  EXPECT_EQ(core.lr(0), std::vector<std::int64_t>(6, 0));  // 2K + 1 lines of M + 1 words
  EXPECT_THROW(core.strobe(3, 10, 4), std::out_of_range) << "does not fit channel_i";
  EXPECT_THROW(core.step(10, 3), std::out_of_range);
  core.clear_flags(4);
  EXPECT_FALSE(core.pins(5).channel_error);
}

TEST(IirCoreChannels, SampleBankMatchesTheCycleModel) {
  const CoreConfig config = load_core_config(loco_ch4_json());
  ASSERT_EQ(config.num_channels, 4);
  IirCore core(config);
  IirSampleBank bank(config);
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> sample(-32768, 32767), channel(0, 3);
  for (int n = 0; n < 200000; ++n) {
    const int c = channel(rng);
    const std::int32_t x = n % 5000 < 500 ? (n % 2 ? 32767 : -32768) : sample(rng);
    const StepResult want = core.step(x, c);
    const SampleResult got = bank.step(x, c);
    ASSERT_EQ(got.sample, want.sample) << "n = " << n;
    ASSERT_EQ(got.saturated, want.saturated) << "n = " << n;
  }
  EXPECT_THROW(bank.step(0, 4), std::out_of_range);
  EXPECT_THROW(IirSampleModel{config}, std::invalid_argument) << "one channel only";
}

TEST(IirCoreChannels, ConfigRulesForChannels) {
  CoreConfig c = three_channels();
  c.coef_sets = 2;
  EXPECT_THROW(validate_core_config(c), std::invalid_argument) << "1 or num_channels sets";
  c = three_channels();
  c.rom.pop_back();
  EXPECT_THROW(validate_core_config(c), std::invalid_argument) << "3 sets of 7 words";
  c = three_channels();
  c.num_channels = kMaxCoreChannels + 1;
  c.coef_sets = 1;
  c.rom.resize(7);
  EXPECT_THROW(validate_core_config(c), std::invalid_argument);
  EXPECT_THROW(three_channels().channel_config(3), std::out_of_range);
  EXPECT_EQ(three_channels().channel_config(1).rom,
            (std::vector<std::int64_t>{0, 0, 0, 8, 2, 4, 0}));
}

TEST(IirCoreChannels, LoaderReadsChannelsAndRejectsBadCounts) {
  const CoreConfig config = load_core_config(loco_ch4_json());
  EXPECT_EQ(config.coef_sets, 1);
  std::ifstream in(loco_ch4_json());
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto write = [&](const std::string& from, const std::string& to) {
    std::string changed = text;
    changed.replace(changed.find(from), from.size(), to);
    const auto path = std::filesystem::temp_directory_path() / "flange_channels_filter.json";
    std::ofstream(path) << changed;
    return path;
  };
  EXPECT_THROW(load_core_config(write("\"coef_sets\": 1", "\"coef_sets\": 3")), FilterJsonError);
  EXPECT_THROW(load_core_config(write("\"coef_sets\": 1", "\"coef_sets\": 4")), FilterJsonError)
      << "4 sets need 4 x rom_depth words";
  EXPECT_THROW(load_core_config(write("\"channels\": 4", "\"channels\": 33")), FilterJsonError);
}

}  // namespace
}  // namespace flange::model
