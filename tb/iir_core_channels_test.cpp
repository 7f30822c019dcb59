// SPDX-License-Identifier: MIT
// Co-simulation of a multichannel iir_core (NumChannels > 1) against model/iir_core.h, pin for pin
// in every cycle, and of each channel against a one-channel model fed that channel's samples
// alone (model::IirSampleBank): channels interleaved, in bursts, idle, overrunning, saturating and
// out of range. Linked into the co-simulation binary of each multichannel set
// (LocoCh12.IirCoreChannels.*).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <random>
#include <vector>

#include "cosim_harness.h"
#include "filter_json.h"
#include "iir_core.h"
#include "iir_core_dut.h"
#include "iir_sample_bank.h"
#include "stimulus.h"

namespace flange::tb {
namespace {

// One strobe of the schedule: the cycle, the sample and its channel.
struct ChannelStrobe {
  std::uint64_t cycle;
  std::int32_t sample;
  int channel;
};

class IirCoreChannels : public ::testing::Test {
 protected:
  void SetUp() override {
    config_ = model::load_core_config(built_coeff_set().filter_json);
    model::IirCore core(config_);
    latency_ = static_cast<std::uint64_t>(core.latency_cycles());
    channel_span_ = 1 << core.channel_width();
    ASSERT_GT(config_.num_channels, 1) << "a multichannel set is expected";
  }

  std::int32_t random_sample(std::mt19937_64& rng, double level = 1.0) const {
    const double full = std::ldexp(1.0, config_.sample_width - 1);
    std::uniform_real_distribution<double> u(-level * full, level * full - 1.0);
    return static_cast<std::int32_t>(std::lround(u(rng)));
  }

  CosimReport run(const std::vector<ChannelStrobe>& strobes) {
    Stimulus stimulus;
    for (const ChannelStrobe& s : strobes) {
      stimulus.add({s.cycle, Action::Kind::kStrobe, s.sample, s.channel});
    }
    CosimHarness harness(config_, make_dut());
    CosimReport report = harness.run(stimulus);
    EXPECT_FALSE(report.rtl_assertion);
    EXPECT_EQ(report.mismatches, 0u) << report.first_mismatch;
    return report;
  }

  // What each channel must give: its accepted samples, alone, through a one-channel model.
  // `accepted` marks the strobes the core took (the others were dropped as overruns).
  std::map<int, std::vector<model::SampleResult>> expected_per_channel(
      const std::vector<ChannelStrobe>& strobes, const std::vector<bool>& accepted) const {
    model::IirSampleBank bank(config_);
    std::map<int, std::vector<model::SampleResult>> out;
    for (std::size_t i = 0; i < strobes.size(); ++i) {
      if (!accepted[i]) continue;
      out[strobes[i].channel].push_back(bank.step(strobes[i].sample, strobes[i].channel));
    }
    return out;
  }

  // Which strobes a core accepts: one while idle, in range; the rest are dropped.
  std::vector<bool> accepted_by_core(const std::vector<ChannelStrobe>& strobes) const {
    std::vector<bool> accepted;
    std::uint64_t ready = 1;
    for (const ChannelStrobe& s : strobes) {
      const bool take = s.cycle >= ready && s.channel < config_.num_channels;
      accepted.push_back(take);
      if (take) ready = s.cycle + latency_;
    }
    return accepted;
  }

  // The DUT's outputs, split by channel_o, against the one-channel models.
  void expect_channels_independent(const std::vector<ChannelStrobe>& strobes,
                                   const CosimReport& report) const {
    const auto expected = expected_per_channel(strobes, accepted_by_core(strobes));
    std::map<int, std::vector<std::int32_t>> got;
    for (std::size_t i = 0; i < report.outputs.size(); ++i) {
      got[report.output_channels[i]].push_back(report.outputs[i]);
    }
    for (const auto& [channel, results] : expected) {
      std::vector<std::int32_t> want;
      for (const model::SampleResult& r : results) want.push_back(r.sample);
      EXPECT_EQ(got[channel], want) << "channel " << channel;
    }
    for (const auto& [channel, samples] : got) {
      EXPECT_TRUE(expected.contains(channel)) << "output on channel " << channel << " never fed";
    }
  }

  model::CoreConfig config_;
  std::uint64_t latency_ = 0;
  int channel_span_ = 0;  // 2^ChannelWidth: channel_i values the port can carry
};

TEST_F(IirCoreChannels, InterleavedBackToBackIsBitExact) {
  std::mt19937_64 rng(1);
  std::vector<ChannelStrobe> strobes;
  std::uint64_t cycle = 1;
  for (int round = 0; round < 400; ++round) {
    for (int c = 0; c < config_.num_channels; ++c, cycle += latency_) {
      strobes.push_back({cycle, random_sample(rng, 0.5), c});
    }
  }
  const CosimReport report = run(strobes);
  EXPECT_EQ(report.accepted, strobes.size());
  EXPECT_EQ(report.dropped, 0u);
  expect_channels_independent(strobes, report);
}

TEST_F(IirCoreChannels, BurstsAndIdleChannelsStayApart) {
  // Bursts of one channel, random gaps; the upper half of the channels is never fed.
  std::mt19937_64 rng(2);
  const int fed = std::max(1, config_.num_channels / 2);
  std::uniform_int_distribution<int> pick(0, fed - 1), burst(1, 40);
  std::uniform_int_distribution<std::uint64_t> gap(0, 3 * latency_);
  std::vector<ChannelStrobe> strobes;
  std::uint64_t cycle = 1;
  while (strobes.size() < 6000) {
    const int channel = pick(rng);
    for (int n = burst(rng); n > 0; --n, cycle += latency_ + gap(rng)) {
      strobes.push_back({cycle, random_sample(rng, 0.9), channel});
    }
  }
  const CosimReport report = run(strobes);
  EXPECT_EQ(report.dropped, 0u);
  EXPECT_EQ(report.saturation_channels >> fed, 0u) << "an idle channel flagged saturation";
  expect_channels_independent(strobes, report);
}

TEST_F(IirCoreChannels, OverrunFlagsOnlyTheDroppedChannel) {
  // Channel 1's strobes come two cycles into another channel's computation: each is dropped and
  // only overrun_o[1] rises; the accepted samples of every channel are unchanged by the drops.
  std::mt19937_64 rng(3);
  std::vector<ChannelStrobe> strobes;
  std::uint64_t cycle = 1;
  for (int round = 0; round < 200; ++round) {
    const int channel = round % config_.num_channels == 1 ? 0 : round % config_.num_channels;
    strobes.push_back({cycle, random_sample(rng, 0.5), channel});
    if (round % 7 == 0) strobes.push_back({cycle + 2, random_sample(rng, 0.5), 1});
    cycle += latency_ + 1;
  }
  const CosimReport report = run(strobes);
  EXPECT_GT(report.dropped, 0u);
  EXPECT_EQ(report.overrun_channels, 1u << 1) << "only channel 1 was ever dropped";
  expect_channels_independent(strobes, report);
}

TEST_F(IirCoreChannels, EveryChannelsOverrunSetsItsOwnBit) {
  // For each channel in turn: clear the flags, drop one of its samples during another channel's
  // computation; the pins are compared with the model every cycle, and the overrun bits seen over
  // the run are every channel's.
  std::mt19937_64 rng(6);
  Stimulus stimulus;
  std::uint64_t cycle = 1;
  for (int c = 0; c < config_.num_channels; ++c) {
    stimulus.add({cycle, Action::Kind::kClear, 0, 0});
    const int other = (c + 1) % config_.num_channels;
    stimulus.add({cycle + 1, Action::Kind::kStrobe, random_sample(rng, 0.5), other});
    stimulus.add({cycle + 3, Action::Kind::kStrobe, random_sample(rng, 0.5), c});
    cycle += 2 * latency_;
  }
  CosimHarness harness(config_, make_dut());
  const CosimReport report = harness.run(stimulus);
  EXPECT_FALSE(report.rtl_assertion);
  EXPECT_EQ(report.mismatches, 0u) << report.first_mismatch;
  EXPECT_EQ(report.dropped, static_cast<std::uint64_t>(config_.num_channels));
  const std::uint32_t every = config_.num_channels == 32 ? ~0u : (1u << config_.num_channels) - 1;
  EXPECT_EQ(report.overrun_channels, every);
}

TEST_F(IirCoreChannels, SaturationOnOneChannelLeavesTheOthers) {
  // Full-scale square wave on channel 0 (the filter's overshoot clips), small noise elsewhere.
  std::mt19937_64 rng(4);
  const std::int32_t top = (1 << (config_.sample_width - 1)) - 1;
  std::vector<ChannelStrobe> strobes;
  std::uint64_t cycle = 1;
  // 400 samples of channel 0 per half period: long enough for the step response to overshoot.
  for (int n = 0; n < 1200 * config_.num_channels; ++n) {
    const int channel = n % config_.num_channels;
    const bool high = (n / config_.num_channels / 400) % 2 == 0;
    const std::int32_t sample = channel == 0 ? (high ? top : -top - 1) : random_sample(rng, 0.1);
    strobes.push_back({cycle, sample, channel});
    cycle += latency_;
  }
  const CosimReport report = run(strobes);
  EXPECT_EQ(report.saturation_channels & 1u, 1u) << "channel 0 was meant to clip";
  EXPECT_EQ(report.saturation_channels & ~1u, 0u) << "saturation leaked to another channel";
  expect_channels_independent(strobes, report);
}

TEST_F(IirCoreChannels, ChannelOutOfRangeIsDroppedAndFlagged) {
  if (channel_span_ == config_.num_channels) {
    GTEST_SKIP() << "every channel_i value is a channel";
  }
  std::mt19937_64 rng(5);
  std::vector<ChannelStrobe> strobes;
  std::uint64_t cycle = 1;
  for (int n = 0; n < 200; ++n, cycle += latency_) {
    const int channel = n % 10 == 9 ? channel_span_ - 1 : n % config_.num_channels;
    strobes.push_back({cycle, random_sample(rng, 0.5), channel});
  }
  const CosimReport report = run(strobes);
  EXPECT_TRUE(report.channel_error_seen);
  EXPECT_EQ(report.overrun_channels, 0u);
  expect_channels_independent(strobes, report);
}

}  // namespace
}  // namespace flange::tb
