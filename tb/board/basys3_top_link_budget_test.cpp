// SPDX-License-Identifier: MIT
// The link budget of the 12-channel board (docs/board.md, "Link budget"), measured on its pins:
// the loco_ch12 top Verilated at a real bit time (ClksPerBit 109, 921600 baud at 100 MHz, unless
// the build sets FLANGE_LINK_BUDGET_CLKS_PER_BIT) streams one second of a six-axle locomotive (12
// channels at 100 Hz, interleaved) through a stop-and-wait host that sends each request the moment
// the previous reply has arrived. Every reply must be bit-exact with its channel's model, the
// cycles per exchange what the documented formula says, and the second of data must take less
// than a second exactly when the formula says it fits.
// Reproduce: build/tb/basys3_top_link_budget_test (prints the measured figures). Another baud rate:
// configure with -DFLANGE_LINK_BUDGET_CLKS_PER_BIT=868 (115200 baud), build this test, run it.
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

TEST(Basys3TopLinkBudget, OneSecondOfTwelveChannelsAt100HzFitsWhenTheFormulaSaysSo) {
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
  std::printf(
      "[link budget] ClksPerBit %d (%.0f baud): %d exchanges in %.0f cycles, %.1f cycles "
      "(%.2f us) per exchange, %.0f samples/s; one second of 12 x 100 Hz took %.3f s\n",
      kSimClksPerBit, kClockHz / kSimClksPerBit, exchanges, cycles, per_exchange,
      per_exchange / kClockHz * 1e6, kClockHz / per_exchange, seconds);
  const auto formula = static_cast<double>(exchange_cycles(kSimClksPerBit, model.latency_cycles()));
  EXPECT_NEAR(per_exchange, formula, 1.0) << "the formula of docs/board.md (link_budget.h)";
  const bool fits = formula * kChannels * kRate < kClockHz;
  EXPECT_EQ(seconds < 1.0, fits) << "12 channels at 100 Hz";
  if (kSimClksPerBit == 109) {
    EXPECT_TRUE(fits) << "docs/board.md: they fit at 921600 baud";
  }
  EXPECT_FALSE(bench.assertion_failed());
}

}  // namespace
}  // namespace flange::tb::board
