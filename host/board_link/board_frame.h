// SPDX-License-Identifier: MIT
// The Basys-3 sample link's frames (docs/board.md), the C++ twin of rtl/board/frame_decoder.sv and
// rtl/board/frame_encoder.sv: host -> board SYNC, SEQ, CHANNEL, SAMPLE_HI, SAMPLE_LO, CRC-8;
// board -> host SYNC, SEQ, CHANNEL, OUT_HI, OUT_LO, STATUS, CRC-8. CRC-8: polynomial 0x07, initial
// value 0, MSB first, no final XOR (CRC-8/SMBUS), over every byte after SYNC.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>

namespace flange::host::board {

inline constexpr std::uint8_t kSync = 0xA5;
inline constexpr std::uint8_t kCommandSync = 0x5A;      // a command frame instead of a sample
inline constexpr std::uint16_t kCommandReset = 0x0001;  // restart the session: reset the filter
inline constexpr std::uint16_t kCommandResetWindowed = 0x0002;  // the same, SEQs in order
inline constexpr std::size_t kRequestBytes = 6;
inline constexpr std::size_t kReplyBytes = 7;

// STATUS bits of a reply. OVERRUN and SATURATION are those of the reply's channel (of every
// channel in the reply to a session reset).
inline constexpr std::uint8_t kStatusOverrun = 1u << 0;     // a frame was dropped: board busy
inline constexpr std::uint8_t kStatusSaturation = 1u << 1;  // the core clipped since the last reply
inline constexpr std::uint8_t kStatusLinkError = 1u << 2;   // bytes discarded since the last reply
inline constexpr std::uint8_t kStatusBypass = 1u << 3;      // OUT is the unfiltered input (sw[0])
inline constexpr std::uint8_t kStatusRetransmit = 1u << 4;  // a repeat of the last reply
inline constexpr std::uint8_t kStatusSessionReset = 1u << 5;  // answers a reset command
inline constexpr std::uint8_t kStatusChannelError = 1u << 6;  // no such channel: not filtered
inline constexpr std::uint8_t kStatusWindowed = 1u << 7;      // a windowed session's reply

inline std::uint8_t crc8(std::span<const std::uint8_t> bytes) {
  std::uint8_t crc = 0;
  for (std::uint8_t byte : bytes) {
    crc ^= byte;
    for (int bit = 0; bit < 8; ++bit) {
      crc = static_cast<std::uint8_t>((crc & 0x80u) ? (crc << 1) ^ 0x07u : crc << 1);
    }
  }
  return crc;
}

struct Request {
  std::uint8_t seq = 0;
  std::uint8_t channel = 0;  // 0..255; the board answers one it lacks with kStatusChannelError
  std::int16_t sample = 0;   // a Q1.15 word
};

inline std::array<std::uint8_t, kRequestBytes> encode_request(const Request& request) {
  const auto bits = static_cast<std::uint16_t>(request.sample);
  std::array<std::uint8_t, kRequestBytes> frame{kSync,
                                                request.seq,
                                                request.channel,
                                                static_cast<std::uint8_t>(bits >> 8),
                                                static_cast<std::uint8_t>(bits & 0xFFu),
                                                0};
  frame[5] = crc8(std::span<const std::uint8_t>(frame).subspan(1, 4));
  return frame;
}

// A command frame: CMD_SYNC, SEQ, CHANNEL, COMMAND_HI, COMMAND_LO, CRC-8 over the four middle
// bytes. The board echoes CHANNEL; a session reset resets every channel whatever it says.
inline std::array<std::uint8_t, kRequestBytes> encode_command(std::uint8_t seq,
                                                              std::uint16_t command,
                                                              std::uint8_t channel = 0) {
  auto frame = encode_request({seq, channel, static_cast<std::int16_t>(command)});
  frame[0] = kCommandSync;
  return frame;
}

struct Reply {
  std::uint8_t seq = 0;
  std::uint8_t channel = 0;
  std::int16_t sample = 0;  // OUT; the channel count in the reply to a session reset
  std::uint8_t status = 0;
  bool operator==(const Reply&) const = default;
};

inline std::array<std::uint8_t, kReplyBytes> encode_reply(const Reply& reply) {
  const auto bits = static_cast<std::uint16_t>(reply.sample);
  std::array<std::uint8_t, kReplyBytes> frame{kSync,
                                              reply.seq,
                                              reply.channel,
                                              static_cast<std::uint8_t>(bits >> 8),
                                              static_cast<std::uint8_t>(bits & 0xFFu),
                                              reply.status,
                                              0};
  frame[6] = crc8(std::span<const std::uint8_t>(frame).subspan(1, 5));
  return frame;
}

// The reply in `frame` (exactly kReplyBytes bytes), or nothing when SYNC or the CRC is wrong.
inline std::optional<Reply> decode_reply(std::span<const std::uint8_t> frame) {
  if (frame.size() != kReplyBytes || frame[0] != kSync) return std::nullopt;
  if (crc8(frame.subspan(1, 5)) != frame[6]) return std::nullopt;
  Reply reply;
  reply.seq = frame[1];
  reply.channel = frame[2];
  reply.sample = static_cast<std::int16_t>(static_cast<std::uint16_t>((frame[3] << 8) | frame[4]));
  reply.status = frame[5];
  return reply;
}

// Finds replies in a byte stream the way the board finds requests: a sliding window, resynchronised
// on the first intact frame after damage. push() returns a reply when the last kReplyBytes bytes
// form one; the bytes of an accepted reply are never reused. discarded() counts the bytes that
// never became part of a reply.
class ReplyScanner {
 public:
  std::optional<Reply> push(std::uint8_t byte) {
    if (fill_ == kReplyBytes) {
      for (std::size_t i = 1; i < kReplyBytes; ++i) window_[i - 1] = window_[i];
      window_[kReplyBytes - 1] = byte;
      ++discarded_;
    } else {
      window_[fill_++] = byte;
    }
    if (fill_ < kReplyBytes) return std::nullopt;
    std::optional<Reply> reply = decode_reply(window_);
    if (reply) fill_ = 0;
    return reply;
  }
  std::uint64_t discarded() const { return discarded_; }

 private:
  std::array<std::uint8_t, kReplyBytes> window_{};
  std::size_t fill_ = 0;
  std::uint64_t discarded_ = 0;
};

}  // namespace flange::host::board
