// SPDX-License-Identifier: MIT
// The link budget of the 12-channel board (docs/board.md, "Link budget"), measured on its pins:
// the loco_ch12 top Verilated at the real bit time of 921600 baud (ClksPerBit 109 at 100 MHz)
// streams one second of a six-axle locomotive (12 channels at 100 Hz, interleaved) through a
// stop-and-wait host that sends each request the moment the previous reply has arrived. The
// simulated time must be under one second, every reply bit-exact with its channel's model, and
// the cycles per exchange what the documented formula says.
// Reproduce: build/tb/basys3_top_link_budget_test (prints the measured figures).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "board_bench.h"
#include "board_frame.h"
#include "filter_json.h"
#include "iir_core.h"
#include "link_budget.h"

namespace flange::tb::board {
namespace {

namespace frame = flange::host::board;

constexpr double kClockHz = 100e6;

TEST(Basys3TopLinkBudget, OneSecondOfTwelveChannelsAt100HzFitsAt921600Baud) {
  ASSERT_EQ(kSimClksPerBit, 109) << "this board build runs at 921600 baud";
  BoardBench bench;
  model::IirCore model(model::load_core_config(kBoardFilterJson));
  constexpr int kChannels = 12;
  constexpr int kRate = 100;
  std::mt19937 rng(100);
  std::uniform_int_distribution<int> word(-30000, 30000);
  const std::uint64_t start = bench.cycle();
  int exchanges = 0;
  for (int n = 0; n < kRate; ++n) {
    for (int c = 0; c < kChannels; ++c) {
      const auto sample = static_cast<std::int16_t>(word(rng));
      const auto seq = static_cast<std::uint8_t>(exchanges);
      const auto f = frame::encode_request({seq, static_cast<std::uint8_t>(c), sample});
      bench.send({f.begin(), f.end()});
      const frame::Reply reply = await_reply(bench);
      const model::StepResult want = model.step(sample, c);
      ASSERT_EQ(reply.seq, seq);
      ASSERT_EQ(reply.channel, c);
      ASSERT_EQ(reply.sample, want.sample) << "channel " << c << " sample " << n;
      ++exchanges;
    }
  }
  const double cycles = static_cast<double>(bench.cycle() - start);
  const double per_exchange = cycles / exchanges;
  const double seconds = cycles / kClockHz;
  std::printf("[link budget] ClksPerBit %d (%.0f baud): %d exchanges in %.0f cycles, %.1f cycles "
              "(%.2f us) per exchange, %.0f samples/s; one second of 12 x 100 Hz took %.3f s\n",
              kSimClksPerBit, kClockHz / kSimClksPerBit, exchanges, cycles, per_exchange,
              per_exchange / kClockHz * 1e6, kClockHz / per_exchange, seconds);
  EXPECT_LT(seconds, 1.0) << "12 channels at 100 Hz do not fit the link at this baud rate";
  EXPECT_NEAR(per_exchange,
              static_cast<double>(exchange_cycles(kSimClksPerBit, model.latency_cycles())), 1.0)
      << "the formula of docs/board.md (link_budget.h)";
  EXPECT_FALSE(bench.assertion_failed());
}

}  // namespace
}  // namespace flange::tb::board
