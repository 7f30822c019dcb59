// SPDX-License-Identifier: MIT
// The board tests' stream of wheel samples: noisy words on each channel, channel c at a level of
// its own, so that the outputs tell the channels apart.
#pragma once

#include <cstdint>
#include <random>
#include <utility>
#include <vector>

#include "channel_stream.h"

namespace flange::tb::board {

// `per_channel` words on each of `channels` channels, from the generator seeded with `seed`.
inline std::vector<host::ChannelWords> wheel_words(int channels, int per_channel, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> noise(-1500, 1500);
  std::vector<host::ChannelWords> out;
  for (int c = 0; c < channels; ++c) {
    host::ChannelWords ch{c, {}};
    const int level = (c % 2 ? 1 : -1) * (5000 + 2100 * c);
    for (int n = 0; n < per_channel; ++n) {
      ch.words.push_back(static_cast<std::int16_t>(level + noise(rng)));
    }
    out.push_back(std::move(ch));
  }
  return out;
}

}  // namespace flange::tb::board
