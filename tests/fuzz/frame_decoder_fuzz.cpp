// SPDX-License-Identifier: MIT
// The host's reply scanner on any byte stream: every reply it reports is an intact frame (SYNC,
// matching CRC-8) made of the last bytes it was fed, and no byte is counted twice.
#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <span>
#include <vector>

#include "board_frame.h"

namespace board = flange::host::board;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  board::ReplyScanner scanner;
  std::size_t in_replies = 0;
  for (std::size_t i = 0; i < size; ++i) {
    const std::optional<board::Reply> reply = scanner.push(data[i]);
    if (!reply) continue;
    if (i + 1 < board::kReplyBytes) std::abort();
    const std::span<const std::uint8_t> frame(data + i + 1 - board::kReplyBytes,
                                              board::kReplyBytes);
    if (frame[0] != board::kSync ||
        board::crc8(frame.subspan(1, board::kReplyBytes - 2)) != frame[board::kReplyBytes - 1]) {
      std::abort();
    }
    const auto encoded = board::encode_reply(*reply);  // the reply says what the bytes say
    if (!std::equal(encoded.begin(), encoded.end(), frame.begin())) std::abort();
    in_replies += board::kReplyBytes;
  }
  if (scanner.discarded() + in_replies > size) std::abort();
  return 0;
}
